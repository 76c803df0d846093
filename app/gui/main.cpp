// SPDX-License-Identifier: GPL-3.0-or-later
// benchscope [WORKSPACE.bsw | FILE/FOLDER...] [--screenshot DIR [--window-size WxH]] [--startup-time]
#include <QApplication>
#include <QComboBox>
#include <QCommandLineParser>
#include <QDir>
#include <QElapsedTimer>
#include <QTabWidget>
#include <QTimer>
#include <cstdio>

#include "headroom/headroom_view.h"
#include "kernels/kernel_runner.h"
#include "main_window.h"
#include "peaks/flops_plot.h"
#include "peaks/peak_table.h"
#include "peaks/roofline_view.h"
#include "platform/efficiency_view.h"
#include "platform/inference_table.h"
#include "platform/platform_view.h"
#include "power/battery_view.h"
#include "power/power_trace_loader.h"
#include "power/power_view.h"
#include "vision/frame_triptych.h"
#include "vision/frames_view.h"
#include "vision/lens_view_3d.h"
#include "vision/pipeline_view.h"
#include "workspace/workspace_tree.h"

namespace {

// Screenshots go into the repository: the smallest PNG zlib can make (quality 0 = strongest compression).
void save_png(QWidget* widget, const QString& path) { widget->grab().save(path, "PNG", 0); }

}  // namespace

int main(int argc, char** argv) {
  QElapsedTimer since_start;  // for --startup-time: from the start of main() to a window that answers events
  since_start.start();
  // VTK views render through QOpenGLWidget: the default format must be set before QApplication exists.
  bs::ui::set_vtk_default_surface_format();

  QApplication app(argc, argv);
  QApplication::setApplicationName("BenchScope");
  QApplication::setOrganizationName("BenchScope");
  QApplication::setApplicationVersion(BENCHSCOPE_VERSION);

  QCommandLineParser cli;
  cli.setApplicationDescription("BenchScope: compare robot computing platforms");
  cli.addHelpOption();
  cli.addVersionOption();
  cli.addPositionalArgument("paths", "A workspace (.bsw) to open, or files/folders to import into a new one.");
  QCommandLineOption shot("screenshot", "Save PNG screenshots of the window and views into DIR, then quit.", "DIR");
  cli.addOption(shot);
  QCommandLineOption sweep("sweep",
                           "Start a Kernel Runner sweep over SPEC workers right away (with --screenshot: "
                           "the shots are taken mid-sweep).",
                           "SPEC");
  cli.addOption(sweep);
  QCommandLineOption size("window-size",
                          "With --screenshot: also save the whole window with each tab in front, at "
                          "this size (e.g. 1280x800), as window-<tab>.png.",
                          "WxH");
  cli.addOption(size);
  QCommandLineOption startup("startup-time",
                             "Print how long the window took to show and answer events (ms from "
                             "start), then quit: the figure issue #19 asks to stay under 2 s.");
  cli.addOption(startup);
  cli.process(app);

  bs::ui::MainWindow window;
  const QStringList paths = cli.positionalArguments();
  if (paths.size() == 1 && paths[0].endsWith(".bsw")) {
    window.open_workspace(paths[0]);
  } else if (!paths.isEmpty()) {
    window.import_paths_now(paths);
  } else {
    window.new_untitled_workspace();
  }
  window.show();
  if (cli.isSet(startup)) {
    // A zero-time timer fires once the event loop runs with the window mapped: from then on the window answers
    // clicks and paints while long power logs load in the background. The line is printed when their samples are in
    // the views (at once when there is nothing to load).
    const qint64 shown_ms = since_start.elapsed();
    QTimer::singleShot(0, &window, [&window, &since_start, shown_ms] {
      const qint64 answering_ms = since_start.elapsed();
      const auto report = [&since_start, shown_ms, answering_ms] {
        std::printf(
            "startup: window shown after %lld ms, answering events after %lld ms, power samples in the views "
            "after %lld ms\n",
            static_cast<long long>(shown_ms), static_cast<long long>(answering_ms),
            static_cast<long long>(since_start.elapsed()));
        std::fflush(stdout);
        QApplication::quit();
      };
      bs::ui::PowerTraceLoader* loader = window.trace_loader();
      if (!loader->running()) return report();
      QObject::connect(loader, &bs::ui::PowerTraceLoader::loaded, &window, report, Qt::QueuedConnection);
      QObject::connect(loader, &bs::ui::PowerTraceLoader::failed, &window, report, Qt::QueuedConnection);
    });
  }
  if (cli.isSet(sweep)) {
    window.kernel_runner()->set_workers_spec(cli.value(sweep));
    window.kernel_runner()->start();
  }

  if (cli.isSet(shot)) {
    const QString dir = cli.value(shot);
    QDir().mkpath(dir);
    const int delay_ms = cli.isSet(sweep) ? 2500 : 500;
    const QString window_size = cli.value(size);
    QTimer::singleShot(delay_ms, &window, [&window, dir, window_size] {
      if (const QStringList wh = window_size.split('x'); wh.size() == 2) {
        // Every tab as a user sees it at that window size: what is clipped or cramped shows here.
        window.resize(wh[0].toInt(), wh[1].toInt());
        auto* tabs = static_cast<QTabWidget*>(window.centralWidget());
        for (int i = 0; i < tabs->count(); ++i) {
          tabs->setCurrentIndex(i);
          for (int k = 0; k < 5; ++k) QApplication::processEvents();
          save_png(&window, dir + "/window-" + tabs->tabText(i).remove('&').toLower() + ".png");
        }
        tabs->setCurrentIndex(0);
        QApplication::quit();
        return;
      }
      save_png(&window, dir + "/main-window.png");
      save_png(window.flops_plot(), dir + "/flops-plot.png");
      save_png(window.peak_table(), dir + "/peak-table.png");
      save_png(window.tree(), dir + "/workspace-tree.png");
      save_png(window.kernel_runner(), dir + "/kernel-runner.png");
      window.power_view()->resize(window.flops_plot()->size());
      save_png(window.power_view(), dir + "/power-view.png");
      window.platform_view()->resize(1900, 540);       // every column of the comparison side by side
      window.platform_view()->set_power_budget(10.0);  // the paper's conclusion: under 10 W the Jetson
      window.platform_view()->set_mission("idle:60:12,walk:30:140,kick:5:225");  // servos per phase
      save_png(window.platform_view(), dir + "/platform-view.png");
      // The mission decides: with the servos' phases only the Jetson lasts 40 minutes.
      window.platform_view()->set_power_budget(std::nullopt);
      window.platform_view()->set_min_runtime_min(40.0);
      save_png(window.platform_view(), dir + "/platform-recommendation.png");
      if (window.platform_view()->inference_table()->isVisible()) {  // bench dnn runs in the workspace
        window.platform_view()->set_min_runtime_min(std::nullopt);
        window.platform_view()->resize(1900, 820);
        save_png(window.platform_view(), dir + "/platform-inference.png");
      }
      window.roofline_view()->resize(1500, 720);  // legend at the side, the note under the plot
      save_png(window.roofline_view(), dir + "/roofline-view.png");
      window.frames_view()->resize(1500, 760);  // three panes side by side need the width
      window.frames_view()->triptych()->wait_until_rendered(60000);
      window.frames_view()->triptych()->inspect_at(2, QPointF(790.5, 300.5));  // the inspector at work
      save_png(window.frames_view(), dir + "/frames-triptych.png");
      window.frames_view()->export_figure(dir + "/figure3-triptych.png", nullptr);  // File > Export Figure 3
      window.pipeline_view()->resize(window.flops_plot()->size());
      save_png(window.pipeline_view(), dir + "/pipeline-view.png");
      window.efficiency_view()->resize(window.flops_plot()->size());
      save_png(window.efficiency_view(), dir + "/efficiency-view.png");
      window.battery_view()->resize(window.flops_plot()->size());
      save_png(window.battery_view(), dir + "/battery-view.png");
      if (window.headroom_view()->chooser()->count() > 0) {  // a headroom measurement in the workspace
        window.headroom_view()->resize(1400, 860);
        save_png(window.headroom_view(), dir + "/headroom-tab.png");
      }
      window.kernel_runner()->cancel();
      QApplication::quit();
    });
  }
  return app.exec();
}
