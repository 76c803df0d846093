// SPDX-License-Identifier: GPL-3.0-or-later
#include "report_writer.h"

#include <QBuffer>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QImage>
#include <QPageLayout>
#include <QPdfWriter>
#include <QSaveFile>
#include <QTemporaryDir>
#include <QTextDocument>
#include <QUrl>

#include <stdexcept>

#include "report/platform_report.h"

namespace bs::ui {
namespace {

struct RenderedFigure {
  QString caption, name;
  QImage image;
  QByteArray png;
};

std::vector<RenderedFigure> render_pngs(const std::vector<FigureTemplate>& templates, const FigureData& data,
                                        FigureOptions o, const CancelToken& cancel,
                                        const std::function<void(int, int, const QString&)>& progress) {
  QTemporaryDir dir;
  if (!dir.isValid()) throw std::runtime_error("cannot create a temporary folder for the report's figures");
  o.formats = {"png"};
  o.dpi = 150;  // on screen and on an A4 page; the figures command gives print resolution
  // A template whose data the workspace lacks (no power log: no fig4) is left out of the report, not an error.
  std::vector<FigureTemplate> usable;
  for (const FigureTemplate& t : templates) {
    try {
      render_figures({t}, data, dir.path(), o, cancel);
      usable.push_back(t);
    } catch (const Cancelled&) {
      throw;
    } catch (const std::runtime_error&) {
    }
  }
  std::vector<RenderedFigure> out;
  int done = 0;
  for (const FigureTemplate& t : usable) {
    if (progress) progress(done++, static_cast<int>(usable.size()) + 1, QString::fromStdString(t.id));
    const QString name = QString::fromStdString(t.id) + ".png";
    QFile f(QDir(dir.path()).filePath(name));
    if (!f.open(QIODevice::ReadOnly)) continue;
    RenderedFigure r{QString::fromStdString(t.title.empty() ? t.id : t.id + ": " + t.title), name, {}, f.readAll()};
    r.image.loadFromData(r.png, "PNG");
    out.push_back(std::move(r));
  }
  return out;
}

// The report's folder is created if missing, as `figures --out` does.
void make_parent(const QString& path) { QDir().mkpath(QFileInfo(path).absolutePath()); }

void save_whole(const QString& path, const QByteArray& bytes) {
  make_parent(path);
  QSaveFile f(path);
  if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size() || !f.commit())
    throw std::runtime_error(path.toStdString() + ": cannot write: " + f.errorString().toStdString());
}

void print_pdf(const QString& path, const std::string& html, const std::vector<RenderedFigure>& figures) {
  make_parent(path);
  QSaveFile file(path);
  if (!file.open(QIODevice::WriteOnly))
    throw std::runtime_error(path.toStdString() + ": cannot write: " + file.errorString().toStdString());
  {
    QPdfWriter pdf(&file);
    pdf.setPageSize(QPageSize(QPageSize::A4));
    pdf.setPageMargins(QMarginsF(15, 15, 15, 15), QPageLayout::Millimeter);
    pdf.setCreator("BenchScope");
    pdf.setTitle("BenchScope report");
    QTextDocument doc;
    for (const RenderedFigure& f : figures) doc.addResource(QTextDocument::ImageResource, QUrl(f.name), f.image);
    doc.setHtml(QString::fromStdString(html));
    doc.print(&pdf);
  }
  if (!file.commit())
    throw std::runtime_error(path.toStdString() + ": cannot write: " + file.errorString().toStdString());
}

std::string number(double v) {
  QString s = QString::number(v, 'g', 4);
  return s.toStdString();
}

}  // namespace

std::string describe_constraints(const Constraints& c) {
  std::string out;
  const auto add = [&](const std::string& s) { out += (out.empty() ? "" : ", ") + s; };
  if (c.power_budget_w) add("a power budget of " + number(*c.power_budget_w) + " W");
  if (c.min_fps) add("at least " + number(*c.min_fps) + " fps");
  if (c.min_runtime_h) add("at least " + number(*c.min_runtime_h * 60) + " min on the battery");
  return out;
}

QStringList write_report(const ReportRequest& request, const std::vector<FigureTemplate>& templates,
                         const FigureData& data, const FigureOptions& figure_options, const CancelToken& cancel,
                         const std::function<void(int, int, const QString&)>& progress) {
  if (request.html_path.isEmpty() && request.pdf_path.isEmpty()) throw std::runtime_error("no report file named");
  const std::vector<RenderedFigure> figures = render_pngs(templates, data, figure_options, cancel, progress);
  cancel.throw_if_cancelled();

  ReportInput in;
  in.workspace = request.workspace_name.toStdString();
  in.generated = QDateTime::currentDateTime().toString(Qt::ISODate).toStdString();
  in.tool = "BenchScope " BENCHSCOPE_VERSION;
  in.rows = compare_platforms(data.runs, data.traces, data.pipelines, request.comparison);
  in.verdicts = recommend(in.rows, request.constraints);
  in.constraints = describe_constraints(request.constraints);
  in.inference_runs = data.inference_runs;
  in.candidates_html = request.candidates_html;

  QStringList written;
  try {
    if (!request.html_path.isEmpty()) {
      ReportInput html_in = in;
      for (const RenderedFigure& f : figures)
        html_in.figures.push_back({f.caption.toStdString(), "data:image/png;base64," + f.png.toBase64().toStdString()});
      save_whole(request.html_path, QByteArray::fromStdString(report_html(html_in)));
      written << request.html_path;
    }
    cancel.throw_if_cancelled();
    if (!request.pdf_path.isEmpty()) {
      ReportInput pdf_in = in;
      for (const RenderedFigure& f : figures) pdf_in.figures.push_back({f.caption.toStdString(), f.name.toStdString()});
      print_pdf(request.pdf_path, report_html(pdf_in), figures);
      written << request.pdf_path;
    }
  } catch (...) {
    for (const QString& f : written) QFile::remove(f);
    throw;
  }
  if (progress) progress(1, 1, "done");
  return written;
}

}  // namespace bs::ui
