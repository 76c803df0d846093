// SPDX-License-Identifier: GPL-3.0-or-later
// The headroom figure through the paper template (kind "headroom", optional), as `benchscope-cli figures`, the
// report and the GUI's Reproduce paper figures render it: the newest measurement drawn with every phase, the older
// one left out and said why, the figure skipped (and said so) without a measurement.
#include <qcustomplot.h>
#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include "../support/file_bytes.h"
#include "../support/headroom_samples.h"
#include "headroom_figure.h"
#include "paper_figures.h"
#include "rendered_figures.h"

using namespace bs::headroom;

namespace {

HeadroomMeasurement measured(const std::string& date, int max_us) {
  return bs::test::loop_measurement("robot",
                                    {{"idle", bs::test::loop_thread(500, 12, {max_us})},
                                     {"pipeline@30fps", bs::test::loop_thread(500, 12, {max_us})}},
                                    date);
}

}  // namespace

class TestHeadroomFigure : public QObject {
  Q_OBJECT
 private slots:
  void paper_template_draws_the_newest_and_skips_without() {
    const auto headroom = bs::test::paper_figures_of_kind("headroom");
    QCOMPARE(headroom.size(), std::size_t{1});
    QVERIFY(headroom[0].optional);
    bs::ui::FigureOptions o;
    o.formats = {"svg", "png"};
    bs::ui::FigureData d;
    d.headroom = {measured("2026-11-27T10:00:00Z", 900), measured("2026-11-28T10:00:00Z", 345)};
    QTemporaryDir dir;
    const auto out = bs::ui::render_figures(headroom, d, dir.path(), o, bs::CancelToken{});
    QVERIFY(out.files.contains(dir.filePath("headroom.svg")) && out.files.contains(dir.filePath("headroom.png")));
    const QByteArray svg = bs::test::bytes_of(dir.filePath("headroom.svg"));
    for (const char* want : {"pipeline@30fps, max 345", "deadline 1000", "Cycles (log scale)"})
      QVERIFY2(svg.contains(want), want);
    QVERIFY(!svg.contains("max 900"));  // the older measurement is not drawn
    const QJsonObject f = bs::test::figures_manifest(dir)["files"].toArray()[0].toObject();
    QCOMPARE(f["figure"].toString(), QString("headroom"));
    QCOMPARE(f["sources"].toArray()[0].toObject()["date"].toString(), QString("2026-11-28T10:00:00Z"));
    QCOMPARE(f["left_out"].toArray().size(), 1);
    QVERIFY(f["left_out"].toArray()[0].toObject()["reason"].toString().startsWith("an older measurement"));

    QTemporaryDir none;
    const auto skipped = bs::ui::render_figures(headroom, bs::ui::FigureData{}, none.path(), o, bs::CancelToken{});
    for (const QString& file : skipped.files) QVERIFY2(!file.contains("headroom."), qPrintable(file));
    QVERIFY2(skipped.contents.join('\n').contains("headroom: not drawn (optional figure): no headroom measurement"),
             qPrintable(skipped.contents.join('\n')));
    // Paper data only: no control loop was measured in the paper, so the figure is skipped too.
    const bs::ui::FigureData paper = bs::ui::select_figure_data(d, bs::ui::FigureDataChoice::PaperOnly);
    QVERIFY(paper.headroom.empty());
  }
};

QTEST_MAIN(TestHeadroomFigure)
#include "test_headroom_figure.moc"
