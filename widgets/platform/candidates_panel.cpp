// SPDX-License-Identifier: GPL-3.0-or-later
#include "platform/candidates_panel.h"

#include <qcustomplot.h>
#include <QFile>
#include <QFileDialog>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSplitter>
#include <QTabWidget>
#include <QTableWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include "analysis/library/graph_benchmarks_table.h"
#include "candidates_figure.h"
#include "common/plot_legend.h"

namespace bs::ui {

QString origin_marker_text(DataOrigin origin) {
  switch (origin) {
    case DataOrigin::Measured:
      return QStringLiteral("● measured");
    case DataOrigin::Reconstructed:
      return QStringLiteral("■ reconstructed");
    case DataOrigin::Published:
      return QStringLiteral("◆ published");
    case DataOrigin::Unknown:
      break;
  }
  return QStringLiteral("? unknown");
}

namespace {

// A table of rows to read, not edit: no row numbers, long cells wrapped, the last column taking the width left.
QTableWidget* read_only_table(QWidget* parent, const QString& name) {
  auto* t = new QTableWidget(parent);
  t->setObjectName(name);
  t->setEditTriggers(QAbstractItemView::NoEditTriggers);
  t->verticalHeader()->setVisible(false);
  t->setWordWrap(true);
  t->horizontalHeader()->setStretchLastSection(true);
  return t;
}

}  // namespace

CandidatesPanel::CandidatesPanel(QWidget* parent) : QWidget(parent) {
  spec_ = new QLineEdit(this);
  spec_->setObjectName(QStringLiteral("library_selection"));
  spec_->setPlaceholderText(tr("library computers, e.g. orin,pi5"));
  spec_->setToolTip(
      tr("Computers from the library of published results (ids or aliases, comma separated), or "
         "result ids: `benchscope-cli library list` lists them"));
  computers_ = new QToolButton(this);
  computers_->setText(tr("Add from library ▾"));
  computers_->setPopupMode(QToolButton::InstantPopup);
  auto* menu = new QMenu(computers_);
  const BundledLibrary& lib = bundled_library();
  for (const LibraryComputer& c : lib.library.computers) {
    QAction* a = menu->addAction(QString::fromStdString(c.name));
    a->setCheckable(true);
    const QString id = QString::fromStdString(c.aliases.empty() ? c.id : c.aliases.front());
    connect(a, &QAction::toggled, this, [this, id](bool on) {
      QStringList words = spec_->text().split(',', Qt::SkipEmptyParts);
      for (QString& w : words) w = w.trimmed();
      words.removeAll(id);
      if (on) words << id;
      set_selection(words.join(','));
      emit selection_edited();
    });
  }
  computers_->setMenu(menu);
  auto* export_csv = new QPushButton(tr("Export CSV…"), this);
  note_ = new QLabel(this);
  note_->setWordWrap(true);
  if (!lib.error.empty())
    note_->setText(tr("The library could not be loaded: %1").arg(QString::fromStdString(lib.error)));

  table_ = read_only_table(this, QStringLiteral("candidates"));
  plot_ = new QCustomPlot(this);
  plot_->setMinimumWidth(320);

  graphs_ = new QWidget(this);
  graph_table_ = read_only_table(graphs_, QStringLiteral("graph_benchmarks"));
  auto* graphs_title = new QLabel(
      tr("<b>ROS 2 graph benchmarks</b> (ros2_benchmark, RobotPerf): compared only within one tool, node, input, "
         "release and measure"),
      graphs_);
  graphs_title->setWordWrap(true);
  auto* export_graphs = new QPushButton(tr("Export CSV…"), graphs_);
  export_graphs->setToolTip(tr("Save the ROS 2 graph benchmark rows as CSV"));
  auto* graphs_top = new QHBoxLayout;
  graphs_top->addWidget(graphs_title, 1);
  graphs_top->addWidget(export_graphs);
  auto* graphs_layout = new QVBoxLayout(graphs_);
  graphs_layout->setContentsMargins(0, 0, 0, 0);
  graphs_layout->addLayout(graphs_top);
  graphs_layout->addWidget(graph_table_, 1);

  auto* top = new QHBoxLayout;
  top->addWidget(new QLabel(tr("Candidates from the library:"), this));
  top->addWidget(spec_, 1);
  top->addWidget(computers_);
  top->addWidget(export_csv);
  auto* split = new QSplitter(Qt::Horizontal, this);
  split->addWidget(table_);
  split->addWidget(plot_);
  split->setStretchFactor(0, 1);
  split->setStretchFactor(1, 1);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addLayout(top);
  layout->addWidget(note_);
  // The graph benchmarks on a page of their own beside the inference candidates: under them, at 1280x800 neither
  // table kept more than a row in view.
  views_ = new QTabWidget(this);
  views_->setObjectName(QStringLiteral("candidate_views"));
  views_->setDocumentMode(true);
  views_->addTab(split, tr("Inference results and peaks"));
  views_->addTab(graphs_, tr("ROS 2 graph benchmarks"));
  views_->setTabVisible(1, false);
  layout->addWidget(views_, 1);
  connect(spec_, &QLineEdit::editingFinished, this, &CandidatesPanel::recompute);
  connect(spec_, &QLineEdit::editingFinished, this, &CandidatesPanel::selection_edited);
  connect(export_csv, &QPushButton::clicked, this, &CandidatesPanel::export_csv);
  connect(export_graphs, &QPushButton::clicked, this, &CandidatesPanel::export_graphs_csv);
}

void CandidatesPanel::set_own(std::vector<PlatformRow> rows, std::vector<PipelineRun> pipelines,
                              std::vector<DnnRun> dnn, std::vector<ResultSet> result_sets,
                              const Constraints& constraints, const ComparisonOptions& options,
                              std::optional<std::vector<headroom::LoopVerdict>> loop,
                              std::optional<std::vector<sustain::SustainVerdict>> sustained) {
  rows_ = std::move(rows);
  loop_ = std::move(loop);
  sustained_ = std::move(sustained);
  pipelines_ = std::move(pipelines);
  dnn_ = std::move(dnn);
  sets_ = std::move(result_sets);
  constraints_ = constraints;
  options_ = options;
  recompute();
}

void CandidatesPanel::showEvent(QShowEvent* event) {
  QWidget::showEvent(event);
  plot_->replot();
}

void CandidatesPanel::set_selection(const QString& spec) {
  spec_->setText(spec);
  recompute();
}

QString CandidatesPanel::selection() const { return spec_->text().trimmed(); }

void CandidatesPanel::recompute() {
  const BundledLibrary& lib = bundled_library();
  CandidateInputs in;
  in.platforms = rows_;
  in.pipelines = pipelines_;
  in.dnn_runs = dnn_;
  in.result_sets = sets_;
  in.lib = &lib.library;
  if (loop_) in.loop = &*loop_;
  if (sustained_) in.sustained = &*sustained_;
  QString note;
  try {
    in.library = select_library(lib.library, selection().toStdString());
  } catch (const std::invalid_argument& e) {
    note = QString::fromStdString(e.what());
  }
  classes_ = rank_candidates(in, constraints_, options_);
  peaks_ = peak_candidates(in);
  fill();
  fill_graphs(in.library);
  const QString plot_note = draw_candidates(*plot_, classes_);
  // Beside the axes, not under them: the Platforms tab leaves this plot little height (at 1280x800 the legend's
  // seven rows under it left the axes 50 px); paper exports put it under them again.
  put_legend_beside(plot_);
  plot_->replot();
  if (lib.error.empty())
    note_->setText((note.isEmpty()
                        ? tr("%n published result(s) from the library beside the own platforms; ranked only within "
                             "one network, scenario and precision.",
                             "", static_cast<int>(in.library.size()))
                        : note) +
                   (plot_note.isEmpty() ? QString() : QStringLiteral(" ") + plot_note));
}

void CandidatesPanel::fill() {
  const bool constrained = constraints_.power_budget_w || constraints_.min_fps || constraints_.min_runtime_h;
  const ExportTable t = candidates_table(classes_, constrained);
  QStringList header;
  for (std::size_t c = 0; c + 1 < t.header.size(); ++c) header << QString::fromStdString(t.header[c]);
  table_->clear();
  table_->setColumnCount(header.size());
  table_->setHorizontalHeaderLabels(header);
  table_->setRowCount(static_cast<int>(t.rows.size()));
  std::size_t row = 0;
  const QColor published_tint(232, 240, 250);
  for (const CandidateClass& k : classes_)
    for (const Candidate& c : k.rows) {
      const auto& cells = t.rows[row];
      QString tip = tr("Source: %1").arg(QString::fromStdString(cells.back()));
      if (!c.power_how.empty()) tip += tr("\nPower: %1").arg(QString::fromStdString(c.power_how));
      if (!c.software.empty()) tip += tr("\nSoftware: %1").arg(QString::fromStdString(c.software));
      if (!c.flags.empty()) tip = QString::fromStdString(flags_text(c.flags)) + "\n\n" + tip;
      for (std::size_t col = 0; col + 1 < cells.size(); ++col) {
        QString text = QString::fromStdString(cells[col]);
        if (col == 3) text = origin_marker_text(c.origin);
        auto* item = new QTableWidgetItem(text);
        item->setToolTip(tip);
        if (col >= 4 && col <= 8) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        if (c.origin == DataOrigin::Published) {
          QFont f = item->font();
          f.setItalic(true);
          item->setFont(f);
          item->setBackground(published_tint);
        }
        if (c.recommended) {
          QFont f = item->font();
          f.setBold(true);
          item->setFont(f);
        }
        table_->setItem(static_cast<int>(row), static_cast<int>(col), item);
      }
      ++row;
    }
  table_->resizeColumnsToContents();
  for (int c = 0; c < table_->columnCount(); ++c) table_->setColumnWidth(c, std::min(table_->columnWidth(c), 260));
  table_->resizeRowsToContents();
}

void CandidatesPanel::fill_graphs(const std::vector<const LibraryResult*>& chosen) {
  graph_classes_ = graph_benchmark_classes(chosen);
  std::size_t n = 0;
  for (const GraphBenchmarkClass& k : graph_classes_) n += k.rows.size();
  views_->setTabVisible(1, n > 0);
  views_->setTabText(1, tr("ROS 2 graph benchmarks (%1)").arg(n));
  views_->setTabToolTip(1, tr("ros2_benchmark and RobotPerf results of the chosen library computers"));
  const ExportTable t = graph_benchmarks_table(graph_classes_, bundled_library().library);
  graph_table_->clear();
  // The source is each row's tooltip (and the CSV's last column), as in the candidates table.
  graph_table_->setColumnCount(static_cast<int>(t.header.size()) - 1);
  QStringList header;
  for (std::size_t c = 0; c + 1 < t.header.size(); ++c) header << QString::fromStdString(t.header[c]);
  graph_table_->setHorizontalHeaderLabels(header);
  graph_table_->setRowCount(static_cast<int>(t.rows.size()));
  const QColor published_tint(232, 240, 250);
  const std::size_t value_column = 2;
  std::size_t row = 0;
  for (const GraphBenchmarkClass& k : graph_classes_)
    for (const LibraryResult* r : k.rows) {
      QString tip = tr("Source: %1").arg(QString::fromStdString(t.rows[row].back()));
      if (!r->software.empty()) tip += tr("\nSoftware: %1").arg(QString::fromStdString(r->software));
      if (!r->date.empty()) tip += tr("\nDate: %1").arg(QString::fromStdString(r->date));
      if (!r->flags.empty()) tip = QString::fromStdString(flags_text(r->flags)) + "\n\n" + tip;
      for (std::size_t col = 0; col + 1 < t.rows[row].size(); ++col) {
        auto* item = new QTableWidgetItem(QString::fromStdString(t.rows[row][col]));
        item->setToolTip(tip);
        if (col == value_column) item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        QFont f = item->font();
        f.setItalic(true);  // published, as in the candidates table
        item->setFont(f);
        item->setBackground(published_tint);
        graph_table_->setItem(static_cast<int>(row), static_cast<int>(col), item);
      }
      ++row;
    }
  graph_table_->resizeColumnsToContents();
  for (int c = 0; c < graph_table_->columnCount(); ++c)
    graph_table_->setColumnWidth(c, std::min(graph_table_->columnWidth(c), 240));
  graph_table_->resizeRowsToContents();
}

namespace {

// Asks where, then writes the table as CSV there; a failed write says so.
void save_table_csv(QWidget* parent, const QString& title, const QString& file_name, const ExportTable& table) {
  const QString path = QFileDialog::getSaveFileName(parent, title, file_name, QObject::tr("CSV (*.csv)"));
  if (path.isEmpty()) return;
  const std::string text = to_csv(table);
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly) ||
      f.write(text.data(), static_cast<qint64>(text.size())) != static_cast<qint64>(text.size()))
    QMessageBox::warning(parent, title, QObject::tr("Cannot write %1").arg(path));
}

}  // namespace

void CandidatesPanel::export_csv() {
  const bool constrained = constraints_.power_budget_w || constraints_.min_fps || constraints_.min_runtime_h;
  save_table_csv(this, tr("Export candidates"), QStringLiteral("candidates.csv"),
                 candidates_table(classes_, constrained));
}

void CandidatesPanel::export_graphs_csv() {
  save_table_csv(this, tr("Export ROS 2 graph benchmarks"), QStringLiteral("ros2-graph-benchmarks.csv"),
                 graph_benchmarks_table(graph_classes_, bundled_library().library));
}

}  // namespace bs::ui
