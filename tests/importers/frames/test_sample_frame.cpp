// SPDX-License-Identifier: GPL-3.0-or-later
// The sample capture (sample_data/paper-2018/frames) is what its README says: the paper's lens, 1280x1024 BGGR
// 8-bit, labelled synthetic, and byte for byte what synth-frame renders today.
#include <QTest>

#include <cstring>

#include "vision/frames/frame_image.h"
#include "vision/frames/synthetic.h"
#include "workspace/registry.h"

class TestSampleFrame : public QObject {
  Q_OBJECT
 private slots:
  void sample_capture_is_the_papers_lens_rendered() {
    const auto batch =
        bs::import_file(BENCHSCOPE_SOURCE_DIR "/sample_data/paper-2018/frames/paper-capture.raw", bs::CancelToken{});
    QCOMPARE(batch.frames.size(), std::size_t{1});
    const bs::Frame& f = batch.frames[0];
    QCOMPARE(f.width, 1280);
    QCOMPARE(f.height, 1024);
    QCOMPARE(f.pattern, std::string("BGGR"));
    QCOMPARE(f.bit_depth, 8);
    QVERIFY(f.synthetic);
    QVERIFY(f.provenance.note.find("synthetic") != std::string::npos);
    const auto fl = bs::vision::lens_for_frame(f);
    QVERIFY(fl.from_frame);
    QCOMPARE(fl.lens.type, bs::vision::LensType::Equidistant);
    QCOMPARE(fl.lens.fov_deg, 195.0);
    QVERIFY(std::abs(fl.lens.r_pp - bs::vision::Lens::paper().r_pp) < 1e-15);
    QCOMPARE(fl.view.fov_deg, 150.0);
    const cv::Mat fresh =
        bs::vision::mosaic(bs::vision::render_fisheye(bs::vision::Lens::paper(), 8), bs::vision::BayerPattern::BGGR);
    QCOMPARE(cv::norm(bs::vision::frame_to_mat(f), fresh, cv::NORM_INF), 0.0);
  }
};

QTEST_APPLESS_MAIN(TestSampleFrame)
#include "test_sample_frame.moc"
