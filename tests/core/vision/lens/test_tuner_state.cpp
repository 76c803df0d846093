// SPDX-License-Identifier: GPL-3.0-or-later
#include <QTemporaryDir>
#include <QTest>
#include <fstream>

#include "../../../support/refusal.h"
#include "vision/lens/tuner_state.h"

using namespace bs::vision;

class TestTunerState : public QObject {
  Q_OBJECT
 private slots:
  void a_drag_of_one_field_is_one_undo_step() {
    TunerState s;
    TunerParams p = s.params();
    for (int yaw = 1; yaw <= 30; ++yaw) {  // a slider drag: 30 changes of yaw
      p.view.yaw_deg = yaw;
      QVERIFY(s.set(p, "yaw"));
    }
    QCOMPARE(s.undo_depth(), std::size_t{1});
    p.lens.r_pp *= 1.01;
    QVERIFY(s.set(p, "r_pp"));
    QCOMPARE(s.undo_depth(), std::size_t{2});
    QVERIFY(s.undo());
    QCOMPARE(s.params().lens.r_pp, TunerParams{}.lens.r_pp);
    QCOMPARE(s.params().view.yaw_deg, 30.0);
    QVERIFY(s.undo());
    QCOMPARE(s.params().view.yaw_deg, 0.0);
    QVERIFY(!s.undo());
    QVERIFY(s.redo());
    QCOMPARE(s.params().view.yaw_deg, 30.0);
    QVERIFY(s.redo());
    QCOMPARE(s.params().lens.r_pp, p.lens.r_pp);
    QVERIFY(!s.redo());
  }
  void end_merge_splits_drags_and_a_new_change_clears_redo() {
    TunerState s;
    TunerParams p = s.params();
    p.view.pitch_deg = 10;
    s.set(p, "pitch");
    s.end_merge();  // slider released
    p.view.pitch_deg = 20;
    s.set(p, "pitch");
    QCOMPARE(s.undo_depth(), std::size_t{2});
    s.undo();
    QCOMPARE(s.params().view.pitch_deg, 10.0);
    QVERIFY(s.can_redo());
    p.view.pitch_deg = 15;
    s.set(p, "pitch");
    QVERIFY(!s.can_redo());
    QVERIFY(!s.set(s.params(), "pitch"));  // no change, no step
  }
  void picked_lines_are_undo_steps_that_keep_the_lens() {
    // The straight-line tool's lines live beside the parameters: each change of them is one step, undo brings
    // them back without touching the lens, and Reset, rebase and lens changes keep them.
    TunerState s;
    TunerParams p = s.params();
    const TunerState::Lines two = {{{1, 2}, {3, 4}, {5, 6}}, {{10, 10}, {20, 20}, {30, 31}}};
    QVERIFY(s.set_lines(two, "propose lines"));
    QVERIFY(!s.set_lines(two, "propose lines"));  // no change, no step
    p.lens.r_pp *= 1.02;
    QVERIFY(s.set(p, "r_pp"));
    QCOMPARE(s.lines().size(), std::size_t{2});
    s.end_merge();
    QVERIFY(s.set_lines({two[0]}, "delete line"));
    QCOMPARE(s.undo_depth(), std::size_t{3});
    QVERIFY(s.undo());
    QCOMPARE(s.lines().size(), std::size_t{2});
    QCOMPARE(s.params().lens.r_pp, p.lens.r_pp);
    QVERIFY(s.undo());
    QCOMPARE(s.params().lens.r_pp, TunerParams{}.lens.r_pp);
    QCOMPARE(s.lines().size(), std::size_t{2});
    QVERIFY(s.undo());
    QVERIFY(s.lines().empty());
    QVERIFY(s.redo());
    QVERIFY(s.lines() == two);
    QVERIFY(s.redo());
    QVERIFY(s.reset());  // the lens goes back, the lines stay
    QVERIFY(s.params() == TunerParams{});
    QVERIFY(s.lines() == two);
    s.rebase(p);
    QVERIFY(s.lines() == two);
    QVERIFY(!s.can_undo());
  }
  void reset_is_undoable_and_rebase_sets_the_baseline() {
    TunerState s;
    TunerParams p = s.params();
    p.view.roll_deg = 5;
    p.masks.push_back({{1, 2}, {30, 2}, {30, 40}});
    s.set(p, "roll");
    QVERIFY(s.reset());
    QVERIFY(s.params() == TunerParams{});
    QVERIFY(s.undo());
    QVERIFY(s.params() == p);
    s.rebase(p);
    QVERIFY(!s.can_undo());
    p.view.roll_deg = 7;
    s.set(p, "roll");
    s.reset();
    QCOMPARE(s.params().view.roll_deg, 5.0);
  }
  void json_round_trip_keeps_lens_view_and_masks() {
    TunerParams p;
    p.lens.type = LensType::KannalaBrandt;
    p.lens.k = {0.01, -0.002, 0.0003, -0.00004};
    p.lens.cx = 641.25;
    p.lens.cy = 500.5;
    p.view = View{800, 600, 110, 12.5, -7.25, 3};
    p.masks = {{{10, 900}, {1270, 900}, {1270, 1023}, {10, 1023}}, {{5.5, 6.25}, {50, 6}, {20, 40}}};
    QTemporaryDir dir;
    const std::string path = dir.filePath("lens.json").toStdString();
    save_tuner_json(p, path);
    const TunerParams q = load_tuner_json(path);
    QVERIFY(q == p);
    // A plain lens file (no masks) loads too.
    const TunerParams plain = tuner_from_json(lens_to_json(p.lens, p.view));
    QVERIFY(plain.masks.empty());
    nlohmann::json bad = tuner_to_json(p);
    bad["masks"][1][2] = {1};
    const QString refusal = bs::test::refusal<std::invalid_argument>([&] { tuner_from_json(bad); });
    QVERIFY2(refusal.contains("/masks/1/2"), qPrintable(refusal));
  }
  void mask_image_fills_the_polygons() {
    const cv::Mat m = mask_image({{{10, 10}, {20, 10}, {20, 20}, {10, 20}}, {{0, 0}, {1, 1}}}, {40, 30});
    QCOMPARE(m.at<std::uint8_t>(15, 15), std::uint8_t{255});
    QCOMPARE(m.at<std::uint8_t>(5, 5), std::uint8_t{0});
    QCOMPARE(cv::countNonZero(m), 11 * 11);
  }
  void exported_lut_reads_back_as_the_exact_map() {
    TunerParams p;
    p.view = View{320, 240, 120, 20, -10, 5};
    const cv::Mat map = build_reprojection_map(p.lens, p.view);
    QTemporaryDir dir;
    const std::string path = dir.filePath("view.bslut").toStdString();
    export_lut(map, p, path);
    nlohmann::json header;
    const cv::Mat back = read_lut(path, &header);
    QCOMPARE(back.size(), map.size());
    QCOMPARE(back.type(), CV_32FC2);
    QCOMPARE(cv::norm(back, map, cv::NORM_INF), 0.0);
    QVERIFY(tuner_from_json(header["lens"]) == p);
    // Truncated payload: rejected with the file named, before anything is allocated from the header.
    std::filesystem::resize_file(path, std::filesystem::file_size(path) - 8);
    try {
      read_lut(path);
      QFAIL("a truncated LUT was accepted");
    } catch (const std::runtime_error& e) {
      QVERIFY2(std::string(e.what()).find("payload") != std::string::npos, e.what());
    }
  }
};

QTEST_GUILESS_MAIN(TestTunerState)
#include "test_tuner_state.moc"
