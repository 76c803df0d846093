// SPDX-License-Identifier: GPL-3.0-or-later
#include "workspace/workspace_tree.h"

#include <QHeaderView>
#include <QKeyEvent>
#include <QMenu>
#include <QPainter>
#include <QPixmap>
#include <map>

#include "device_palette.h"
#include "report/run_names.h"
#include "store/record_kinds.h"

namespace bs::ui {
namespace {

constexpr int kRunIdRole = Qt::UserRole + 1;
constexpr int kKindRole = Qt::UserRole + 2;  // TreeItemRef::Kind of an item below the runs or of a platform
constexpr int kIdRole = Qt::UserRole + 3;
constexpr int kImportRole = Qt::UserRole + 4;
constexpr int kNameRole = Qt::UserRole + 5;
constexpr int kSectionRole = Qt::UserRole + 6;  // set on the section headers ("Power logs (2)")
constexpr int kColorRole = Qt::UserRole + 7;    // a device row's colour index
constexpr int kPaletteSize = 15;                // device_palette.cpp's distinct colours

// A record kind's section is named by its descriptor (store/record_kinds.h), so a new kind needs no title here.
QString section_title(TreeItemRef::Kind kind) {
  using K = TreeItemRef::Kind;
  static const std::map<K, RecordKindId> records = {
      {K::PowerLog, RecordKindId::PowerLog},        {K::Frame, RecordKindId::Frame},
      {K::PipelineRun, RecordKindId::PipelineRun},  {K::ResultSet, RecordKindId::ResultSet},
      {K::Headroom, RecordKindId::Headroom},        {K::InferenceRun, RecordKindId::InferenceRun},
      {K::SustainedRun, RecordKindId::SustainedRun}};
  if (kind == K::BatteryPreset) return WorkspaceTree::tr("Battery presets");
  const auto it = records.find(kind);
  return it == records.end() ? QString() : WorkspaceTree::tr(words_of(it->second).section);
}

QIcon swatch(const QColor& color) {
  QPixmap pm(12, 12);
  pm.fill(Qt::transparent);
  QPainter p(&pm);
  p.setPen(color.darker(140));
  p.setBrush(color);
  p.drawRoundedRect(QRectF(0.5, 0.5, 11, 11), 2, 2);
  return QIcon(pm);
}

QString provenance_tooltip(const FlopsRun& run) {
  const Provenance& p = run.provenance;
  QStringList lines;
  lines << QStringLiteral("<b>%1</b> — %2, D = %3, N = %L4")
               .arg(QString::fromStdString(run.device).toHtmlEscaped(),
                    QString::fromStdString(run.backend).toHtmlEscaped())
               .arg(run.dims)
               .arg(run.iterations);
  lines << QStringLiteral("Origin: <b>%1</b>").arg(QString::fromUtf8(to_string(p.origin).data()));
  auto add = [&](const char* label, const std::string& v) {
    if (!v.empty()) lines << QStringLiteral("%1: %2").arg(label, QString::fromStdString(v).toHtmlEscaped());
  };
  add("Host", p.host);
  add("CPU", p.cpu_model);
  add("GPU", p.gpu_model);
  add("Compiler", p.compiler);
  add("Tool", p.tool);
  add("Date", p.date);
  add("File", p.source_file);
  add("Note", p.note);
  return QStringLiteral("<p style='white-space:pre-wrap; width:420px'>%1</p>").arg(lines.join("<br>"));
}

QStandardItem* child_named(QStandardItem* parent, const QString& text) {
  for (int r = 0; r < parent->rowCount(); ++r)
    if (parent->child(r)->text() == text) return parent->child(r);
  auto* item = new QStandardItem(text);
  item->setCheckable(true);
  item->setAutoTristate(true);
  item->setCheckState(Qt::Checked);
  item->setEditable(false);
  parent->appendRow(item);
  return item;
}

}  // namespace

WorkspaceTree::WorkspaceTree(QWidget* parent) : QTreeView(parent) {
  setModel(&model_);
  setHeaderHidden(true);
  setUniformRowHeights(true);
  setToolTip(
      tr("Tick runs to show them in the plot and the peak table. Right-click, F2 (rename) or Delete "
         "(remove the import that brought an item) to edit; Ctrl+Z undoes."));
  setContextMenuPolicy(Qt::CustomContextMenu);
  connect(this, &QWidget::customContextMenuRequested, this, &WorkspaceTree::show_menu);
  connect(&model_, &QStandardItemModel::itemChanged, this, &WorkspaceTree::on_item_changed);
}

void WorkspaceTree::set_items(const std::vector<WorkspaceItem>& items) {
  updating_ = true;
  QStandardItem* root = model_.invisibleRootItem();
  for (int r = root->rowCount() - 1; r >= 0; --r)
    if (root->child(r)->data(kSectionRole).isValid()) root->removeRow(r);
  std::map<TreeItemRef::Kind, QStandardItem*> sections;
  for (const WorkspaceItem& it : items) {
    QStandardItem*& section = sections[it.ref.kind];
    if (!section) {
      section = new QStandardItem(section_title(it.ref.kind));
      section->setEditable(false);
      section->setData(static_cast<int>(it.ref.kind), kSectionRole);
      QFont bold = section->font();
      bold.setBold(true);
      section->setFont(bold);
      root->appendRow(section);
    }
    auto* row = new QStandardItem(it.text);
    row->setEditable(false);
    row->setToolTip(it.tooltip);
    row->setData(static_cast<int>(it.ref.kind), kKindRole);
    row->setData(QVariant::fromValue<qint64>(it.ref.id), kIdRole);
    row->setData(QVariant::fromValue<qint64>(it.ref.import_id), kImportRole);
    row->setData(it.ref.name, kNameRole);
    section->appendRow(row);
  }
  for (auto& [kind, section] : sections)
    section->setText(QStringLiteral("%1 (%2)").arg(section->text()).arg(section->rowCount()));
  updating_ = false;
}

int WorkspaceTree::item_count(TreeItemRef::Kind kind) const {
  const QStandardItem* root = model_.invisibleRootItem();
  for (int r = 0; r < root->rowCount(); ++r)
    if (root->child(r)->data(kSectionRole).isValid() &&
        root->child(r)->data(kSectionRole).toInt() == static_cast<int>(kind))
      return root->child(r)->rowCount();
  return 0;
}

TreeItemRef WorkspaceTree::ref_at(const QModelIndex& index) const {
  TreeItemRef ref;
  const QStandardItem* item = model_.itemFromIndex(index);
  if (!item || item->data(kSectionRole).isValid()) return ref;
  if (item->data(kRunIdRole).isValid()) {
    ref.kind = TreeItemRef::Kind::Run;
    ref.id = item->data(kRunIdRole).toLongLong();
    ref.import_id = item->data(kImportRole).toLongLong();
    ref.name = item->data(kNameRole).toString();  // the run's label: what a rename changes
  } else if (item->data(kKindRole).isValid()) {
    ref.kind = static_cast<TreeItemRef::Kind>(item->data(kKindRole).toInt());
    ref.id = item->data(kIdRole).toLongLong();
    ref.import_id = item->data(kImportRole).toLongLong();
    ref.name = item->data(kNameRole).toString();
  } else if (!item->parent()) {  // a top-level row that is not a section: a platform of the runs
    ref.kind = TreeItemRef::Kind::Platform;
    ref.name = item->text();
  } else if (item->data(kColorRole).isValid()) {
    ref.kind = TreeItemRef::Kind::Device;
    ref.name = item->text();
    ref.platform = item->parent()->text();
    ref.color_index = item->data(kColorRole).toInt();
  }
  return ref;
}

void WorkspaceTree::show_menu(const QPoint& pos) {
  const TreeItemRef ref = ref_at(indexAt(pos));
  QMenu menu(this);
  if (ref.kind == TreeItemRef::Kind::Device) {
    // Colour is the device's, in every view and export: pick another palette entry (colour-blind-safe first).
    QMenu* colors = menu.addMenu(tr("Colour"));
    for (int i = 0; i < kPaletteSize; ++i) {
      QAction* a = colors->addAction(swatch(device_color(i)), tr("Palette colour %1").arg(i + 1), this,
                                     [this, ref, i] { emit color_requested(ref, i); });
      a->setCheckable(true);
      a->setChecked(i == ref.color_index % kPaletteSize);
    }
    menu.exec(viewport()->mapToGlobal(pos));
    return;
  }
  if (!ref.renamable() && !ref.removable()) return;
  if (ref.renamable()) menu.addAction(tr("Rename…\tF2"), this, [this, ref] { emit rename_requested(ref); });
  if (ref.kind == TreeItemRef::Kind::PowerLog) {
    menu.addAction(tr("Supply voltage…"), this, [this, ref] { emit supply_voltage_requested(ref); })
        ->setToolTip(tr("Voltage that turns this log's current into power: typed, or another log's channel"));
    menu.addAction(tr("Platform…"), this, [this, ref] { emit platform_requested(ref); });
  }
  if (ref.removable())
    menu.addAction(
        ref.kind == TreeItemRef::Kind::BatteryPreset ? tr("Remove preset\tDel") : tr("Remove its import\tDel"), this,
        [this, ref] { emit remove_requested(ref); });
  menu.exec(viewport()->mapToGlobal(pos));
}

void WorkspaceTree::keyPressEvent(QKeyEvent* event) {
  const TreeItemRef ref = current_ref();
  if (event->key() == Qt::Key_F2 && ref.renamable()) {
    emit rename_requested(ref);
    return;
  }
  if (event->matches(QKeySequence::Delete) && ref.removable()) {
    emit remove_requested(ref);
    return;
  }
  QTreeView::keyPressEvent(event);
}

void WorkspaceTree::set_runs(const std::vector<StoredRun>& runs, const std::map<std::int64_t, std::string>& labels) {
  updating_ = true;
  model_.clear();
  QStandardItem* root = model_.invisibleRootItem();
  // Row texts that read apart within each backend (distinct_names adds date and time, host, N where needed).
  std::vector<RunIdentity> identities;
  for (const StoredRun& s : runs) {
    const FlopsRun& r = s.run;
    // A sweep from another tool (Google Benchmark) states FLOPS, not D and N: its family and counter name it.
    const QString text =
        r.dims > 0 ? QStringLiteral("D = %1 · %2 · N = %L3 · %4 pts")
                         .arg(r.dims)
                         .arg(QString::fromStdString(r.variant))
                         .arg(r.iterations)
                         .arg(r.samples.size())
                   : QStringLiteral("%1 · %2 pts").arg(QString::fromStdString(r.variant)).arg(r.samples.size());
    const auto label = labels.find(s.id);
    // Platform, device and backend are the tree's parents: they keep rows of different series from reading alike.
    RunIdentity id = run_identity(r, r.platform + '\x1f' + r.device + '\x1f' + r.backend + '\x1f' + text.toStdString(),
                                  label == labels.end() ? std::string() : label->second);
    id.detail.clear();  // N is in the row already
    identities.push_back(std::move(id));
  }
  const std::vector<std::string> names = distinct_names(identities);
  std::size_t index = 0;
  for (const StoredRun& s : runs) {
    const FlopsRun& r = s.run;
    QStandardItem* platform = child_named(root, QString::fromStdString(r.platform));
    QStandardItem* device = child_named(platform, QString::fromStdString(r.device));
    device->setIcon(swatch(device_color(s.color_index)));
    device->setData(s.color_index, kColorRole);
    QStandardItem* backend = child_named(device, QString::fromStdString(r.backend));
    std::string name = names[index++];
    name.erase(0, name.rfind('\x1f') + 1);  // the parents' part of the identity
    auto* item = new QStandardItem(QString::fromStdString(name));
    const auto label = labels.find(s.id);
    item->setData(label == labels.end() ? QString() : QString::fromStdString(label->second), kNameRole);
    item->setData(QVariant::fromValue<qint64>(s.id), kRunIdRole);
    // Sweeps derived from stored Google Benchmark results (negative ids) are removed with their result set's import.
    item->setData(QVariant::fromValue<qint64>(s.import_id), kImportRole);
    item->setCheckable(true);
    item->setEditable(false);
    item->setCheckState(hidden_.contains(s.id) ? Qt::Unchecked : Qt::Checked);
    item->setToolTip(provenance_tooltip(r));
    backend->appendRow(item);
  }
  // Parent check states follow their children (autoTristate only updates on user changes).
  std::function<Qt::CheckState(QStandardItem*)> sync = [&](QStandardItem* it) -> Qt::CheckState {
    if (!it->hasChildren()) return it->checkState();
    int checked = 0, unchecked = 0;
    for (int r = 0; r < it->rowCount(); ++r) {
      const auto st = sync(it->child(r));
      if (st == Qt::Checked)
        ++checked;
      else if (st == Qt::Unchecked)
        ++unchecked;
    }
    const auto st = checked == it->rowCount()     ? Qt::Checked
                    : unchecked == it->rowCount() ? Qt::Unchecked
                                                  : Qt::PartiallyChecked;
    if (it != model_.invisibleRootItem()) it->setCheckState(st);
    return st;
  };
  sync(root);
  updating_ = false;
  expandToDepth(1);
}

void WorkspaceTree::on_item_changed(QStandardItem* item) {
  if (updating_) return;
  updating_ = true;
  // Propagate a parent's state to its subtree, then recompute the ancestors.
  std::function<void(QStandardItem*, Qt::CheckState)> down = [&](QStandardItem* it, Qt::CheckState st) {
    for (int r = 0; r < it->rowCount(); ++r) {
      it->child(r)->setCheckState(st);
      down(it->child(r), st);
    }
  };
  if (item->checkState() != Qt::PartiallyChecked) down(item, item->checkState());
  for (QStandardItem* p = item->parent(); p; p = p->parent()) {
    int checked = 0, unchecked = 0;
    for (int r = 0; r < p->rowCount(); ++r) {
      if (p->child(r)->checkState() == Qt::Checked)
        ++checked;
      else if (p->child(r)->checkState() == Qt::Unchecked)
        ++unchecked;
    }
    p->setCheckState(checked == p->rowCount()     ? Qt::Checked
                     : unchecked == p->rowCount() ? Qt::Unchecked
                                                  : Qt::PartiallyChecked);
  }
  updating_ = false;
  // Remember hidden runs so a reload (after an import) keeps the user's choice.
  QSet<qint64> visible = visible_runs();
  std::function<void(QStandardItem*)> note_hidden = [&](QStandardItem* it) {
    const QVariant id = it->data(kRunIdRole);
    if (id.isValid()) {
      if (visible.contains(id.toLongLong()))
        hidden_.remove(id.toLongLong());
      else
        hidden_.insert(id.toLongLong());
    }
    for (int r = 0; r < it->rowCount(); ++r) note_hidden(it->child(r));
  };
  note_hidden(model_.invisibleRootItem());
  emit visibility_changed(visible);
}

void WorkspaceTree::collect(const QStandardItem* item, QSet<qint64>& out) const {
  const QVariant id = item->data(kRunIdRole);
  if (id.isValid() && item->checkState() == Qt::Checked) out.insert(id.toLongLong());
  for (int r = 0; r < item->rowCount(); ++r) collect(item->child(r), out);
}

QSet<qint64> WorkspaceTree::visible_runs() const {
  QSet<qint64> out;
  collect(model_.invisibleRootItem(), out);
  return out;
}

QStandardItem* WorkspaceTree::find_run(QStandardItem* parent, qint64 run_id) const {
  for (int r = 0; r < parent->rowCount(); ++r) {
    QStandardItem* c = parent->child(r);
    if (c->data(kRunIdRole).isValid() && c->data(kRunIdRole).toLongLong() == run_id) return c;
    if (QStandardItem* found = find_run(c, run_id)) return found;
  }
  return nullptr;
}

void WorkspaceTree::set_run_visible(qint64 run_id, bool visible) {
  if (QStandardItem* item = find_run(model_.invisibleRootItem(), run_id))
    item->setCheckState(visible ? Qt::Checked : Qt::Unchecked);
}

bool WorkspaceTree::select_run(qint64 run_id) {
  QStandardItem* item = find_run(model_.invisibleRootItem(), run_id);
  if (!item) return false;
  for (QStandardItem* p = item->parent(); p; p = p->parent()) expand(p->index());
  setCurrentIndex(item->index());
  scrollTo(item->index());
  return true;
}

int WorkspaceTree::run_count() const {
  int n = 0;
  std::function<void(const QStandardItem*)> count = [&](const QStandardItem* it) {
    if (it->data(kRunIdRole).isValid()) ++n;
    for (int r = 0; r < it->rowCount(); ++r) count(it->child(r));
  };
  count(model_.invisibleRootItem());
  return n;
}

}  // namespace bs::ui
