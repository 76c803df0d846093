// SPDX-License-Identifier: GPL-3.0-or-later
#include "paper_figures.h"

#include <qcustomplot.h>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "analysis/peaks/flag_notes.h"
#include "analysis/peaks/flops.h"
#include "analysis/platform/paper_tables.h"
#include "analysis/platform/platform_comparison.h"
#include "analysis/platform/platform_table.h"
#include "analysis/power/power.h"
#include "chart_marks.h"
#include "device_palette.h"
#include "headroom_figure.h"
#include "inference_figure.h"
#include "plot_export.h"
#include "plot_labels.h"
#include "report/run_names.h"
#include "triptych_figure.h"
#include "util/resources.h"

namespace bs::ui {
namespace {

struct PageSize {
  double w_pt, h_pt, w_mm, h_mm;
};

PageSize page(const FigureOptions& o) {
  const QSizeF pt = figure_size_pt(o);
  return {pt.width(), pt.height(), o.width_mm, pt.height() * 25.4 / 72.0};
}

void style_axes(QCustomPlot& plot, const FigureTemplate& t, const FigureOptions& o) {
  for (QCPAxis* axis : {plot.xAxis, plot.yAxis}) {
    style_figure_axis(axis, o);
    axis->grid()->setPen(QPen(QColor(0xdd, 0xdd, 0xdd), 0.4, Qt::DotLine));
  }
  plot.xAxis->setLabel(QString::fromStdString(t.x_label));
  plot.yAxis->setLabel(QString::fromStdString(t.y_label));
  if (t.log_x) {
    plot.xAxis->setScaleType(QCPAxis::stLogarithmic);
    plot.xAxis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
    plot.xAxis->setNumberFormat("eb");
    plot.xAxis->setNumberPrecision(0);
  }
  if (t.log_y) {
    plot.yAxis->setScaleType(QCPAxis::stLogarithmic);
    plot.yAxis->setTicker(QSharedPointer<QCPAxisTickerLog>(new QCPAxisTickerLog));
  }
  // The legend goes below the axes, in columns, so it can never cover data at any size (layout_figure).
  plot.legend->setFont(figure_font(o, 0.9));
  plot.legend->setVisible(true);
}

// "Jetson GPU (Pascal, 256 cores)" -> "Jetson GPU", "CPU SIMD (AVX/SSE)" -> "CPU SIMD": the full names stay in
// figures.json, the legend stays short enough for a column.
std::string short_device(const std::string& device) {
  const auto paren = device.find(" (");
  return paren == std::string::npos || paren == 0 ? device : device.substr(0, paren);
}

int color_of(const FigureData& d, const std::string& platform, const std::string& device) {
  const auto it = d.colors.find({platform, device});
  return it == d.colors.end() ? 0 : it->second;
}

QJsonObject source_of(const FlopsRun& r) {
  return {{"platform", QString::fromStdString(r.platform)},
          {"device", QString::fromStdString(r.device)},
          {"backend", QString::fromStdString(r.backend)},
          {"dims", r.dims},
          {"file", QString::fromStdString(r.provenance.source_file)},
          {"origin", QString::fromUtf8(to_string(r.provenance.origin).data())}};
}

// Fills the plot with the template's FLOPS series; returns the data sources. Series that would read alike add what
// differs (run label, date and time, host, N); repeats of one series take their own marker. A flagged peak is drawn
// where it was measured, as a hollow marker labelled "⚠[n]", and the figure's note gives footnote n.
QJsonArray flops_figure(QCustomPlot& plot, const FigureTemplate& t, const FigureData& d, const FigureOptions& o) {
  QJsonArray sources;
  double y_max = 0, x_min = 1e300, x_max = 0;
  std::set<int> dims;  // the legend names D only when the figure shows more than one
  std::vector<std::size_t> chosen;
  for (std::size_t i = 0; i < d.runs.size(); ++i)
    if (t.selects(d.runs[i]) && !flops_curve(d.runs[i]).empty()) {
      dims.insert(d.runs[i].dims);
      chosen.push_back(i);
    }
  std::vector<RunIdentity> identities;
  for (const std::size_t i : chosen) {
    const FlopsRun& run = d.runs[i];
    std::string name = short_device(run.device) + ", " + short_device(run.backend);
    if (dims.size() > 1) name += ", D = " + std::to_string(run.dims);
    identities.push_back(run_identity(run, name, i < d.run_labels.size() ? d.run_labels[i] : std::string()));
  }
  const std::vector<std::string> names = distinct_names(identities);
  std::map<std::string, int> repeats;
  FlagNotes notes;
  auto* labels = new AnchoredLabels(&plot);
  struct Flagged {
    double x, y;
    QString text;
    QColor color;
  };
  std::vector<Flagged> flagged;
  for (std::size_t k = 0; k < chosen.size(); ++k) {
    const FlopsRun& run = d.runs[chosen[k]];
    const auto curve = flops_curve(run);
    QVector<double> xs, ys;
    for (const CurvePoint& p : curve) {
      xs.push_back(static_cast<double>(p.workers));
      ys.push_back(p.flops.mean / t.y_scale);
      y_max = std::max(y_max, ys.back());
      x_min = std::min(x_min, xs.back());
      x_max = std::max(x_max, xs.back());
    }
    QCPGraph* g = plot.addGraph();
    g->setData(xs, ys, true);
    const QColor color = device_color(color_of(d, run.platform, run.device));
    g->setPen(QPen(color, o.line_width_pt, dims_pen_style(run.dims)));
    // Backend by marker (a few per curve): two backends of one device stay apart in colour and in greyscale; a
    // repeated run of the same series takes a marker of its own.
    const int repeat = repeats[run.platform + '\x1f' + identities[k].base]++;
    g->setScatterStyle(QCPScatterStyle(
        static_cast<QCPScatterStyle::ScatterShape>(run_marker_shape(QString::fromStdString(run.backend), repeat)),
        color, Qt::white, o.font_pt * 0.55));
    g->setScatterSkip(std::max(1, static_cast<int>(xs.size()) / 8));
    g->setName(QString::fromStdString(names[k]));
    labels->add_curve(g);
    QJsonObject source = source_of(run);
    const std::vector<PeakRow> peak = peak_table(std::span<const FlopsRun>(&run, 1));
    if (!peak.empty() && !peak.front().flags.empty()) {
      const PeakRow& p = peak.front();
      const std::string marker = notes.marker(p.flags);
      auto* point = plot.addGraph();
      point->setData({static_cast<double>(p.peak.workers)}, {p.peak.flops / t.y_scale});
      point->setLineStyle(QCPGraph::lsNone);
      point->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, color, color, o.font_pt * 0.9));
      mark_flagged_points(point, color);
      point->removeFromLegend();
      flagged.push_back({static_cast<double>(p.peak.workers), p.peak.flops / t.y_scale,
                         flag_label(QString::number(p.peak.flops / t.y_scale, 'f', 2), QString::fromStdString(marker)),
                         color});
      QJsonArray flags;
      for (const PlausibilityFlag& f : p.flags)
        flags.append(
            QJsonObject{{"code", QString::fromStdString(f.code)}, {"reason", QString::fromStdString(f.reason)}});
      source["flags"] = flags;
    }
    sources.append(source);
  }
  if (chosen.empty()) throw NoFigureData(t.id + ": no runs match the template's selection");
  // Labels in order of value: where two would collide, the higher keeps its label.
  std::stable_sort(flagged.begin(), flagged.end(), [](const Flagged& a, const Flagged& b) { return a.y > b.y; });
  for (const Flagged& f : flagged) labels->add(f.x, f.y, f.text, f.color)->setColor(kFlagColor);
  // The footnotes in short (the first sentence of each reason); figures.json and the report carry them whole.
  for (const std::string& line : notes.lines())
    add_figure_note(plot, QStringLiteral("\u26A0") + QString::fromStdString(short_flag_line(line)));
  plot.xAxis->setRange(t.log_x ? std::max(1.0, x_min) : 0, x_max);
  plot.yAxis->setRange(0, y_max * 1.08);
  return sources;
}

QJsonArray current_figure(QCustomPlot& plot, const FigureTemplate& t, const FigureData& d, const FigureOptions& o,
                          QJsonArray& left_out) {
  QJsonArray sources;
  double y_max = 0, x_max = 0;
  std::map<std::string, int> platform_colors, logs_of_platform;
  {
    std::vector<std::pair<std::string, int>> devices;
    for (const auto& [key, index] : d.colors) devices.emplace_back(key.first, index);
    std::vector<std::string> platforms;
    for (const PowerTrace& trace : d.traces) platforms.push_back(trace.platform);
    for (const auto& [platform, index] : platform_color_indices(devices, platforms)) platform_colors[platform] = index;
  }
  std::vector<QCPGraph*> trace_graphs;
  std::vector<RunIdentity> trace_ids;
  const auto leave_out = [&](const PowerTrace& trace, const std::string& reason) {
    left_out.append(QJsonObject{{"platform", QString::fromStdString(trace.platform)},
                                {"file", QString::fromStdString(trace.provenance.source_file)},
                                {"reason", QString::fromStdString(reason)}});
  };
  for (const PowerTrace& trace : d.traces) {
    if (!t.platforms.empty() &&
        std::find(t.platforms.begin(), t.platforms.end(), trace.platform) == t.platforms.end()) {
      std::string names;
      for (const std::string& p : t.platforms) names += (names.empty() ? "" : ", ") + p;
      leave_out(trace, "not one of the figure's platforms (" + names + ")");
      continue;
    }
    const std::vector<double> amps = current_series(trace);
    if (amps.empty() || trace.time_s.empty()) {
      leave_out(trace, "the log has no current channel (the figure plots current, as the paper's Figure 4)");
      continue;
    }
    // At most ~2000 points per trace (min and max of each bucket), so a long log stays a small vector file.
    const std::size_t n = amps.size(), buckets = std::min<std::size_t>(n, 1000);
    QVector<double> xs, ys;
    for (std::size_t b = 0; b < buckets; ++b) {
      const std::size_t lo = b * n / buckets, hi = std::max(lo + 1, (b + 1) * n / buckets);
      // Missing samples (NaN) are left out; a bucket with none present adds no point (the line bridges it).
      double mn = std::numeric_limits<double>::infinity(), mx = -mn;
      for (std::size_t k = lo; k < hi; ++k)
        if (!std::isnan(amps[k])) mn = std::min(mn, amps[k]), mx = std::max(mx, amps[k]);
      if (!(mn <= mx)) continue;
      const double t0 = trace.time_s[lo] - trace.time_s.front();
      xs << t0 << t0;
      ys << mn << mx;
      y_max = std::max(y_max, mx);
    }
    x_max = std::max(x_max, trace.time_s.back() - trace.time_s.front());
    QCPGraph* g = plot.addGraph();
    g->setData(xs, ys, true);
    // The platform's colour, as the Power and Battery tabs and the report's chart give it (one mapping:
    // platform_color_indices); a second log of a platform keeps that colour with another line style (a colour of its
    // own would be another platform's), and the legend names what differs.
    const int logs_before = logs_of_platform[trace.platform]++;
    static const std::array<Qt::PenStyle, 4> kLogStyles = {Qt::SolidLine, Qt::DashLine, Qt::DotLine, Qt::DashDotLine};
    g->setPen(QPen(device_color(platform_colors.at(trace.platform)), o.line_width_pt * 0.6,
                   kLogStyles[static_cast<std::size_t>(logs_before) % kLogStyles.size()]));
    g->setName(QString::fromStdString(trace.platform));
    trace_graphs.push_back(g);
    trace_ids.push_back({trace.platform, "", trace.provenance.date, trace.provenance.host, trace.label});
    sources.append(QJsonObject{{"platform", QString::fromStdString(trace.platform)},
                               {"file", QString::fromStdString(trace.provenance.source_file)},
                               {"origin", QString::fromUtf8(to_string(trace.provenance.origin).data())}});
  }
  if (plot.graphCount() == 0) throw NoFigureData(t.id + ": no current logs for the template's platforms");
  // Two logs of one platform: the legend adds what differs (the log's label, date and time, host, file).
  const std::vector<std::string> names = distinct_names(trace_ids);
  for (std::size_t i = 0; i < trace_graphs.size(); ++i) trace_graphs[i]->setName(QString::fromStdString(names[i]));
  plot.xAxis->setRange(0, x_max);
  plot.yAxis->setRange(0, y_max * 1.1);
  return sources;
}

// "fig4: NUC, Jetson TX2 (reconstructed); left out: RobotPC (not one of the figure's platforms ...)".
QString contents_line(const FigureTemplate& t, const QJsonArray& sources, const QJsonArray& left_out) {
  QStringList shown;
  for (const auto& v : sources) {
    const QJsonObject s = v.toObject();
    QString what = s.contains("what") ? s.value("what").toString()
                   : s.value("device").toString().isEmpty()
                       ? s.value("platform").toString()
                       : s.value("device").toString() + " " + s.value("backend").toString();
    if (s.contains("dims")) what += QStringLiteral(" D=%1").arg(s.value("dims").toInt());
    if (const QString origin = s.value("origin").toString(); !origin.isEmpty()) what += " (" + origin + ")";
    if (!shown.contains(what)) shown << what;
  }
  QString line =
      QString::fromStdString(t.id) + ": " + (shown.isEmpty() ? QObject::tr("the capture") : shown.join(", "));
  QStringList out;
  for (const auto& v : left_out) {
    const QJsonObject l = v.toObject();
    out << (l.contains("what") ? l.value("what").toString() : l.value("platform").toString()) + " (" +
               l.value("reason").toString() + ")";
  }
  if (!out.isEmpty()) line += QObject::tr("; left out: ") + out.join("; ");
  return line;
}

void write_text(const QString& path, const std::string& text, QStringList& files) {
  QFile f(path);
  if (!f.open(QIODevice::WriteOnly) ||
      f.write(text.data(), static_cast<qint64>(text.size())) != static_cast<qint64>(text.size()))
    throw std::runtime_error(path.toStdString() + ": cannot write");
  files << path;
}

}  // namespace

QFont figure_font(const FigureOptions& o, double scale) {
  QFont f("DejaVu Sans");
  f.setPointSizeF(o.font_pt * scale);
  return f;
}

void style_figure_axis(QCPAxis* axis, const FigureOptions& o) {
  axis->setLabelFont(figure_font(o));
  axis->setTickLabelFont(figure_font(o, 0.9));
  axis->setBasePen(QPen(Qt::black, o.line_width_pt * 0.6));
  axis->setTickPen(QPen(Qt::black, o.line_width_pt * 0.6));
  axis->setSubTickPen(QPen(Qt::black, o.line_width_pt * 0.4));
}

FigureData select_figure_data(FigureData d, FigureDataChoice choice) {
  if (choice == FigureDataChoice::All) return d;
  const auto measured = [](const Provenance& p) { return p.origin != DataOrigin::Reconstructed; };
  std::vector<FlopsRun> runs;
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < d.runs.size(); ++i) {
    if (measured(d.runs[i].provenance)) continue;
    runs.push_back(std::move(d.runs[i]));
    labels.push_back(i < d.run_labels.size() ? d.run_labels[i] : std::string());
  }
  d.runs = std::move(runs);
  d.run_labels = std::move(labels);
  std::erase_if(d.traces, [&](const PowerTrace& t) { return measured(t.provenance); });
  std::erase_if(d.pipelines, [](const PipelineTimings& p) { return p.source.origin != DataOrigin::Reconstructed; });
  std::erase_if(d.inference_runs, [](const DnnRun& r) { return r.provenance.origin != DataOrigin::Reconstructed; });
  d.headroom.clear();  // the paper measured no control loop
  d.selection = "paper data only (reconstructed from the paper's reported figures)";
  return d;
}

// Found like every bundled resource (util/resources.h): $BENCHSCOPE_RESOURCE_DIR, an installed share/benchscope,
// then this source tree. When none has it, the source tree's path, so the error names a real place.
QString paper_template_path() {
  try {
    return QString::fromStdString(find_resource("figures/paper-2018.json").string());
  } catch (const std::exception&) {
    return QStringLiteral(BENCHSCOPE_SOURCE_DIR "/resources/figures/paper-2018.json");
  }
}

PlotFigure figure_plot(QCustomPlot& plot, const FigureTemplate& t, const FigureData& data, const FigureOptions& o,
                       QJsonArray& left_out) {
  const PageSize p = page(o);
  plot.resize(static_cast<int>(p.w_pt), static_cast<int>(p.h_pt));
  style_axes(plot, t, o);
  PlotFigure out;
  out.sources = t.kind == "flops"       ? flops_figure(plot, t, data, o)
                : t.kind == "inference" ? inference_figure(plot, t, data.inference_runs, o, left_out)
                : t.kind == "headroom"  ? headroom_template_figure(plot, t, data.headroom, left_out)
                                        : current_figure(plot, t, data, o, left_out);
  // The one figure layout (plot_export.h): legend below, sized to content, nothing clipped.
  out.sized = layout_figure(plot, o);
  const QSizeF size = figure_size_pt(out.sized);
  plot.resize(static_cast<int>(std::lround(size.width())), static_cast<int>(std::lround(size.height())));
  return out;
}

namespace {

// Renders every template and table into out_dir; `out.files` grows as files are written, so a caller can remove
// them when this throws.
void render_all(const std::vector<FigureTemplate>& templates, const FigureData& data, const QString& out_dir,
                const FigureOptions& o, const CancelToken& cancel,
                const std::function<void(int, int, const QString&)>& progress, FigureOutput& out) {
  QJsonArray list, skipped;
  const PageSize p = page(o);
  const int total = static_cast<int>(templates.size()) + 1;
  int done = 0;
  for (const FigureTemplate& t : templates) {
    cancel.throw_if_cancelled();
    if (progress) progress(done, total, QString::fromStdString(t.id));
    const QString stem = QDir(out_dir).filePath(QString::fromStdString(t.id));
    QStringList files;
    QJsonArray sources, left_out;
    double figure_height_mm = p.h_mm;
    try {
      if (t.kind == "triptych") {
        sources = render_triptych_figure(stem, o, files, figure_height_mm, data.frame ? &*data.frame : nullptr, cancel);
      } else {
        QCustomPlot plot;
        FigureOptions sized;
        try {
          PlotFigure figure = figure_plot(plot, t, data, o, left_out);
          sources = figure.sources;
          sized = figure.sized;
        } catch (const NoFigureData& e) {
          if (!t.optional) throw;
          // An optional figure without data: skipped, and said so (figures.json "skipped", the contents line).
          std::string reason = e.what();
          if (reason.starts_with(t.id + ": ")) reason.erase(0, t.id.size() + 2);
          skipped.append(
              QJsonObject{{"figure", QString::fromStdString(t.id)}, {"reason", QString::fromStdString(reason)}});
          out.contents << QString::fromStdString(t.id + ": not drawn (optional figure): " + reason);
          ++done;
          continue;
        }
        save_plot(plot, stem, sized, QString::fromStdString(t.title), files, &cancel);
        figure_height_mm = sized.height_mm;
      }
    } catch (...) {
      out.files << files;
      throw;
    }
    for (const QString& f : files) {
      list.append(QJsonObject{{"file", QFileInfo(f).fileName()},
                              {"figure", QString::fromStdString(t.id)},
                              {"title", QString::fromStdString(t.title)},
                              {"width_mm", p.w_mm},
                              {"height_mm", figure_height_mm},
                              {"sources", sources},
                              {"left_out", left_out}});
    }
    out.contents << contents_line(t, sources, left_out);
    out.files << files;
    ++done;
  }
  cancel.throw_if_cancelled();
  if (progress) progress(done, total, "tables");
  QJsonArray run_sources;
  for (const FlopsRun& r : data.runs) run_sources.append(source_of(r));
  QJsonArray platform_sources = run_sources;
  for (const PowerTrace& t : data.traces)
    platform_sources.append(QJsonObject{{"platform", QString::fromStdString(t.platform)},
                                        {"file", QString::fromStdString(t.provenance.source_file)},
                                        {"origin", QString::fromUtf8(to_string(t.provenance.origin).data())}});
  const std::vector<PlatformRow> rows = compare_platforms(data.runs, data.traces, data.pipelines);
  const std::pair<const char*, ExportTable> tables[] = {{"table1", gpu_peak_table(data.runs)},
                                                        {"table2", cpu_peak_table(data.runs)},
                                                        {"platforms", platform_table(rows)}};
  for (const auto& [stem, table] : tables) {
    for (const char* ext : {".tex", ".csv"}) {
      const QString name = QString(stem) + ext;
      write_text(QDir(out_dir).filePath(name), ext == std::string(".tex") ? to_latex(table) : to_csv(table), out.files);
      QJsonArray notes;  // the plausibility footnotes the table carries (analysis/flag_notes.h)
      for (const std::string& n : table.notes) notes.append(QString::fromStdString(n));
      list.append(QJsonObject{{"file", name},
                              {"figure", stem},
                              {"title", QString::fromStdString(table.caption)},
                              {"sources", std::string(stem) == "platforms" ? platform_sources : run_sources},
                              {"notes", notes}});
    }
  }
  const QByteArray json = QJsonDocument(QJsonObject{{"format", "benchscope-figure-list"},
                                                    {"version", 1},
                                                    {"data", QString::fromStdString(data.selection)},
                                                    {"files", list},
                                                    {"skipped", skipped}})
                              .toJson();
  write_text(QDir(out_dir).filePath("figures.json"), json.toStdString(), out.files);
  if (progress) progress(total, total, "done");
}

}  // namespace

FigureOutput render_figures(const std::vector<FigureTemplate>& templates, const FigureData& data,
                            const QString& out_dir, const FigureOptions& o, const CancelToken& cancel,
                            const std::function<void(int, int, const QString&)>& progress) {
  if (!QDir().mkpath(out_dir)) throw std::runtime_error(out_dir.toStdString() + ": cannot create the folder");
  FigureOutput out;
  try {
    render_all(templates, data, out_dir, o, cancel, progress, out);
  } catch (...) {
    // Cancelled or failed: leave no partial set behind (a figures.json naming files that are not there).
    for (const QString& f : out.files) QFile::remove(f);
    throw;
  }
  return out;
}

}  // namespace bs::ui
