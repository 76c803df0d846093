// SPDX-License-Identifier: GPL-3.0-or-later
#include "inference_figure.h"

#include <qcustomplot.h>
#include <QFontMetricsF>
#include <QJsonObject>

#include <algorithm>
#include <cstdio>
#include <map>
#include <tuple>

#include "device_palette.h"
#include "paper_figures.h"
#include "plot_export.h"

namespace bs::ui {
namespace {

int backend_rank(const std::string& b) {
  if (b == "cpu") return 0;
  if (b == "opencl") return 1;
  if (b == "cuda") return 2;
  return 3;
}

std::string input_text(const DnnRun& r) { return std::to_string(r.input_width) + "x" + std::to_string(r.input_height); }

// "vm mobilenet-ssd 300x300 cpu (architecture timing)": how a run is named in figures.json and the contents line.
std::string what(const DnnRun& r) {
  return r.platform + " " + r.model + " " + input_text(r) + (r.batch > 1 ? " batch " + std::to_string(r.batch) : "") +
         " " + r.backend + (r.architecture_only ? " (architecture timing)" : "");
}

QJsonObject left_out_entry(const DnnRun& r, const std::string& reason) {
  return {{"platform", QString::fromStdString(r.platform)},
          {"what", QString::fromStdString(what(r))},
          {"reason", QString::fromStdString(reason)}};
}

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, v < 10 ? "%.2f" : "%.1f", v);
  return b;
}

}  // namespace

std::string inference_bar_label(const DnnRun& r) {
  return r.platform + "\n" + r.model + " " + input_text(r) + (r.batch > 1 ? ", batch " + std::to_string(r.batch) : "");
}

std::vector<DnnRun> inference_figure_runs(const FigureTemplate& t, const std::vector<DnnRun>& runs,
                                          QJsonArray& left_out) {
  using Key = std::tuple<std::string, std::string, int, int, int, std::string>;
  std::map<Key, DnnRun> newest;
  for (const DnnRun& r : runs) {
    if (!t.platforms.empty() && std::find(t.platforms.begin(), t.platforms.end(), r.platform) == t.platforms.end()) {
      std::string names;
      for (const std::string& p : t.platforms) names += (names.empty() ? "" : ", ") + p;
      left_out.append(left_out_entry(r, "not one of the figure's platforms (" + names + ")"));
      continue;
    }
    const Key key{r.platform, r.model_hash, r.input_width, r.input_height, r.batch, r.backend};
    const auto it = newest.find(key);
    if (it == newest.end()) {
      newest.emplace(key, r);
      continue;
    }
    // ISO 8601 dates sort as text; the older of two runs of the same thing is left out, and said so.
    DnnRun older = r;
    if (it->second.provenance.date < r.provenance.date) std::swap(older, it->second);
    left_out.append(left_out_entry(
        older, "an older run (" + older.provenance.date + ") of the same platform, network, input and target"));
  }
  std::vector<DnnRun> out;
  for (auto& [key, r] : newest) out.push_back(std::move(r));
  std::sort(out.begin(), out.end(), [](const DnnRun& a, const DnnRun& b) {
    return std::forward_as_tuple(a.platform, a.model, a.input_width, a.input_height, a.batch) <
               std::forward_as_tuple(b.platform, b.model, b.input_width, b.input_height, b.batch) ||
           (std::forward_as_tuple(a.platform, a.model, a.input_width, a.input_height, a.batch) ==
                std::forward_as_tuple(b.platform, b.model, b.input_width, b.input_height, b.batch) &&
            std::make_pair(backend_rank(a.backend), a.backend) < std::make_pair(backend_rank(b.backend), b.backend));
  });
  return out;
}

QJsonArray inference_figure(QCustomPlot& plot, const FigureTemplate& t, const std::vector<DnnRun>& all,
                            const FigureOptions& o, QJsonArray& left_out) {
  const std::vector<DnnRun> runs = inference_figure_runs(t, all, left_out);
  if (runs.empty())
    throw NoFigureData(t.id + ": no bench dnn runs" + (t.platforms.empty() ? "" : " of the template's platforms") +
                       " in the data");
  // Horizontal bars (names of any length fit on the left), top to bottom in the runs' order: one series per target
  // and kind (trained model or architecture timing), so the legend names both; the bars of one platform and
  // network stand together, a gap between groups.
  struct Series {
    QCPBars* bars;
    QCPErrorBars* errors;
  };
  std::map<std::pair<int, std::pair<std::string, bool>>, Series> series;
  auto ticker = QSharedPointer<QCPAxisTickerText>(new QCPAxisTickerText);
  QFont small = plot.yAxis->tickLabelFont();
  small.setPointSizeF(o.font_pt * 0.75);
  constexpr double kBarWidth = 0.8, kGroupGap = 0.6;
  double y = 0, group_start = 0, x_max = 0;
  std::string group;
  QJsonArray sources;
  std::vector<QCPItemText*> texts;
  const auto close_group = [&](double end) { ticker->addTick((group_start + end) / 2, QString::fromStdString(group)); };
  for (const DnnRun& r : runs) {
    const std::string label = inference_bar_label(r);
    if (label != group) {
      if (!group.empty()) {
        close_group(y - 1);
        y += kGroupGap;
      }
      group = label;
      group_start = y;
    }
    const auto key = std::make_pair(backend_rank(r.backend), std::make_pair(r.backend, r.architecture_only));
    auto it = series.find(key);
    if (it == series.end()) {
      const QColor color = device_color(backend_rank(r.backend));
      auto* bars = new QCPBars(plot.yAxis, plot.xAxis);
      bars->setWidth(kBarWidth);
      bars->setPen(QPen(color, o.line_width_pt * 0.8));
      QColor fill = color;
      if (!r.architecture_only) fill.setAlpha(190);
      bars->setBrush(QBrush(fill, r.architecture_only ? Qt::BDiagPattern : Qt::SolidPattern));
      bars->setName(QString::fromStdString(r.backend +
                                           (r.architecture_only ? std::string(", ") + kArchitectureTimingLabel : "")));
      auto* errors = new QCPErrorBars(plot.yAxis, plot.xAxis);
      errors->setDataPlottable(bars);
      errors->setPen(QPen(Qt::black, o.line_width_pt * 0.6));
      errors->removeFromLegend();
      it = series.emplace(key, Series{bars, errors}).first;
    }
    const double per_image = r.inference_s() / t.y_scale;
    const double sd = (r.batch > 0 ? r.forward.sd_s / r.batch : 0) / t.y_scale;
    it->second.bars->addData(y, per_image);
    it->second.errors->addData(sd);
    x_max = std::max(x_max, per_image + sd);
    auto* text = new QCPItemText(&plot);
    text->setFont(small);
    text->setPositionAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    text->position->setAxes(plot.xAxis, plot.yAxis);
    text->position->setCoords(per_image + sd, y);
    text->setPadding(QMargins(3, 0, 0, 0));
    text->setClipToAxisRect(false);
    text->setText(
        QString::fromStdString(number(per_image) + " ± " + number(sd) + ", n = " + std::to_string(r.forward.n)));
    texts.push_back(text);
    sources.append(QJsonObject{{"platform", QString::fromStdString(r.platform)},
                               {"what", QString::fromStdString(what(r))},
                               {"device", QString::fromStdString(r.device)},
                               {"backend", QString::fromStdString(r.backend)},
                               {"model", QString::fromStdString(r.model)},
                               {"model_hash", QString::fromStdString(r.model_hash)},
                               {"input", QString::fromStdString(input_text(r))},
                               {"batch", r.batch},
                               {"n", static_cast<qint64>(r.forward.n)},
                               {"architecture_only", r.architecture_only},
                               {"label", r.architecture_only ? QString(kArchitectureTimingLabel) : QString()},
                               {"date", QString::fromStdString(r.provenance.date)},
                               {"origin", QString::fromUtf8(to_string(r.provenance.origin).data())}});
    y += 1;
  }
  close_group(y - 1);
  plot.yAxis->setTicker(ticker);
  plot.yAxis->setSubTicks(false);
  plot.yAxis->setTickLength(0, 3);
  plot.yAxis->grid()->setVisible(false);
  plot.yAxis->setRangeReversed(true);  // the first run at the top
  plot.yAxis->setRange(-kBarWidth / 2 - 0.3, y - 1 + kBarWidth / 2 + 0.3);
  // Room on the right for the widest value label: the axis is laid out once to learn its width in pixels.
  plot.xAxis->setRange(0, x_max);
  plot.setViewport(QRect(QPoint(0, 0), plot.size()));  // a hidden widget gets no resize event to set it
  plot.replot(QCustomPlot::rpImmediateRefresh);
  const double axis_px = std::max(1, plot.axisRect()->width());
  double label_px = 0;
  for (QCPItemText* text : texts)
    label_px = std::max(label_px, QFontMetricsF(small).horizontalAdvance(text->text()) + 6);
  const double fraction = std::min(0.6, label_px / axis_px);  // of the axis the labels need
  plot.xAxis->setRange(0, x_max / (1 - fraction) * 1.02);
  return sources;
}

}  // namespace bs::ui
