// SPDX-License-Identifier: GPL-3.0-or-later
// The Platforms view on the paper's sample data: the recommendation follows the constraints, the best value of a
// column is highlighted, numeric sorting, columns without data hidden, sources in tooltips.
#include <filesystem>

#include <QTableWidget>
#include <QSignalSpy>
#include <QTest>

#include "importer.h"
#include "platform_view.h"

namespace {

void load_paper(std::vector<bs::FlopsRun>& runs, std::vector<bs::PowerTrace>& traces) {
  for (const auto& e : std::filesystem::recursive_directory_iterator(BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018")) {
    const auto ext = e.path().extension();
    if (!e.is_regular_file() || (ext != ".json" && ext != ".csv")) continue;
    if (e.path().parent_path().filename() == "frames") continue;  // the sample capture's sidecar is not data
    auto b = bs::import_file(e.path().string(), bs::CancelToken{});
    runs.insert(runs.end(), b.runs.begin(), b.runs.end());
    traces.insert(traces.end(), b.power_traces.begin(), b.power_traces.end());
  }
}

int column(const QTableWidget* t, const QString& header) {
  for (int c = 0; c < t->columnCount(); ++c)
    if (t->horizontalHeaderItem(c)->text() == header) return c;
  return -1;
}

int row_of(const QTableWidget* t, const QString& platform) {
  for (int r = 0; r < t->rowCount(); ++r)
    if (t->item(r, 0)->text() == platform) return r;
  return -1;
}

}  // namespace

class TestPlatformView : public QObject {
  Q_OBJECT
 private slots:
  void paper_sample() {
    std::vector<bs::FlopsRun> runs;
    std::vector<bs::PowerTrace> traces;
    load_paper(runs, traces);
    bs::ui::PlatformView view;
    view.resize(1500, 500);
    view.set_data(runs, traces);
    QCOMPARE(view.recommendation(), QString("NUC"));
    view.set_power_budget(10.0);
    QCOMPARE(view.recommendation(), QString("Jetson TX2"));
    view.set_power_budget(5.0);
    QCOMPARE(view.recommendation(), QString());
    view.set_power_budget(std::nullopt);

    QTableWidget* t = view.table();
    QCOMPARE(t->rowCount(), 4);
    const int power = column(t, "Mean power (W)");
    QVERIFY(power > 0);
    QCOMPARE(t->item(row_of(t, "Jetson TX2"), power)->text(), QString("9.48"));
    QVERIFY(t->item(row_of(t, "Jetson TX2"), power)->font().bold());   // lowest power is best
    QVERIFY(!t->item(row_of(t, "NUC"), power)->font().bold());
    const int paper = column(t, "GFLOPS/W (paper: peak / max power)");
    QCOMPARE(t->item(row_of(t, "NUC"), paper)->text(), QString("104.64"));
    QVERIFY(t->item(row_of(t, "NUC"), paper)->font().bold());
    QVERIFY(t->item(row_of(t, "NUC"), power)->toolTip().contains("nuc-current.csv"));

    // Numeric sort: ascending mean power puts the Jetson first and the platforms without a log last.
    t->sortItems(power, Qt::AscendingOrder);
    QCOMPARE(t->item(0, 0)->text(), QString("Jetson TX2"));
    QCOMPARE(t->item(1, 0)->text(), QString("NUC"));
    t->sortItems(power, Qt::DescendingOrder);
    QCOMPARE(t->item(0, 0)->text(), QString("NUC"));
    QCOMPARE(t->item(3, 0)->text().isEmpty(), false);

    // No pipeline runs in the paper's sample: those columns are hidden.
    QVERIFY(t->isColumnHidden(column(t, "Preprocessing (ms)")));
    QVERIFY(!t->isColumnHidden(power));

    // Double-click asks for the source of the cell.
    QSignalSpy spy(&view, &bs::ui::PlatformView::source_requested);
    const int gpu = column(t, "GPU peak (GFLOPS)");
    emit t->cellDoubleClicked(row_of(t, "NUC"), gpu);
    QCOMPARE(spy.count(), 1);
    QCOMPARE(spy.at(0).at(1).toString(), QString("gpu_peak"));
  }
};

QTEST_MAIN(TestPlatformView)
#include "test_platform_view.moc"
