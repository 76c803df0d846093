// SPDX-License-Identifier: GPL-3.0-or-later
// The concurrent pipeline: bounded queues under both policies, ordering, timing counts, cancellation within a
// frame, the real preprocessing paths on the paper's lens, and the detectors' output handling.
#include <atomic>
#include <chrono>
#include <thread>

#include <QTest>

#include "vision/bounded_queue.h"
#include "vision/pipeline.h"
#include "vision/preprocess.h"
#include "vision/synthetic.h"

using namespace bs::vision;

namespace {

FrameSource small_frames(int n) {
  return [n](std::size_t i) -> std::optional<cv::Mat> {
    if (static_cast<int>(i) >= n) return std::nullopt;
    return cv::Mat(16, 16, CV_8UC1, cv::Scalar(static_cast<double>(i % 256)));
  };
}

Preprocessor to_bgr() {
  return [](const cv::Mat& m) {
    cv::Mat out;
    cv::merge(std::vector<cv::Mat>{m, m, m}, out);
    return out;
  };
}

}  // namespace

class TestPipeline : public QObject {
  Q_OBJECT
 private slots:
  void block_queue_keeps_everything_in_order() {
    BoundedQueue<int> q(3, QueuePolicy::Block);
    std::thread producer([&] {
      for (int i = 0; i < 50; ++i) QCOMPARE(q.push(i), std::size_t{0});
      q.close();
    });
    std::vector<int> got;
    while (auto v = q.pop()) {
      got.push_back(*v);
      std::this_thread::sleep_for(std::chrono::microseconds(200));  // a slow consumer
    }
    producer.join();
    QCOMPARE(got.size(), std::size_t{50});
    for (int i = 0; i < 50; ++i) QCOMPARE(got[static_cast<std::size_t>(i)], i);
    QVERIFY(q.high_water() <= 3);
  }

  void drop_oldest_keeps_the_newest() {
    BoundedQueue<int> q(2, QueuePolicy::DropOldest);
    std::size_t dropped = 0;
    for (int i = 0; i < 10; ++i) dropped += q.push(i);
    QCOMPARE(dropped, std::size_t{8});
    q.close();
    QCOMPARE(*q.pop(), 8);
    QCOMPARE(*q.pop(), 9);
    QVERIFY(!q.pop());
  }

  void every_frame_through_every_stage() {
    std::atomic<int> detected{0};
    Detector det = [&](const cv::Mat& bgr) {
      ++detected;
      return std::vector<Detection>{{cv::Rect(0, 0, 4, 4), bgr.at<cv::Vec3b>(0, 0)[0] * 1.0, 1}};
    };
    const auto r = run_pipeline(small_frames(40), to_bgr(), det, {.max_frames = 100, .queue_capacity = 2}, bs::CancelToken{});
    QCOMPARE(r.captured, std::size_t{40});
    QCOMPARE(r.processed, std::size_t{40});
    QCOMPARE(r.dropped, std::size_t{0});
    QCOMPARE(detected.load(), 40);
    QCOMPARE(r.stages.size(), std::size_t{3});
    for (const auto& s : r.stages) QCOMPARE(s.summary.n, std::size_t{40});
    // The last frame detected is the last captured (frames stay in order): its value is 39.
    QCOMPARE(r.last_detections.at(0).score, 39.0);
    // End-to-end includes both stages and the queues.
    QVERIFY(r.stage("end-to-end")->summary.mean >= r.stage("detection")->summary.mean);
    QVERIFY(r.stage("end-to-end")->p99 >= r.stage("end-to-end")->p50);
    QVERIFY(r.throughput_fps > 0);
  }

  void slow_detector_with_drop_oldest_drops_frames() {
    Detector slow = [](const cv::Mat&) {
      std::this_thread::sleep_for(std::chrono::milliseconds(3));
      return std::vector<Detection>{};
    };
    const auto r = run_pipeline(small_frames(200), to_bgr(), slow,
                                {.max_frames = 200, .queue_capacity = 1, .policy = QueuePolicy::DropOldest},
                                bs::CancelToken{});
    QCOMPARE(r.captured, std::size_t{200});
    QVERIFY(r.dropped > 0);
    QCOMPARE(r.processed + r.dropped, r.captured);
  }

  void cancel_stops_within_a_frame() {
    bs::CancelToken cancel;
    std::atomic<int> calls{0};
    Detector det = [&](const cv::Mat&) {
      if (++calls == 3) cancel.cancel();
      return std::vector<Detection>{};
    };
    const auto r = run_pipeline(small_frames(100000), to_bgr(), det, {.max_frames = 100000, .queue_capacity = 2}, cancel);
    QVERIFY(r.cancelled);
    QCOMPARE(calls.load(), 3);  // no detection after the one that cancelled
    QVERIFY(r.captured < 100);  // the capture stopped too, within the queues' slack
  }

  void preprocessing_only() {
    // Without a detector the preprocessing stage ends the pipeline; no frame may be lost.
    const auto r = run_pipeline(small_frames(25), to_bgr(), Detector{}, {.queue_capacity = 1}, bs::CancelToken{});
    QCOMPARE(r.processed, std::size_t{25});
    QCOMPARE(r.stages.size(), std::size_t{2});
    QCOMPARE(r.stage("preprocessing")->summary.n, std::size_t{25});
    QVERIFY(!r.stage("detection"));
  }

  void a_failing_stage_is_reported() {
    Preprocessor bad = [](const cv::Mat&) -> cv::Mat { throw std::runtime_error("broken stage"); };
    bool threw = false;
    try {
      const auto r = run_pipeline(small_frames(10), bad, Detector{}, PipelineConfig{}, bs::CancelToken{});
      QFAIL(qPrintable(QString("no exception; %1 frames processed").arg(r.processed)));
    } catch (const std::runtime_error& e) {
      threw = std::string(e.what()) == "broken stage";
    }
    QVERIFY(threw);
  }

  void paper_lens_fused_and_separate_agree() {
    // The paper's lens scaled to a quarter of its size (the same field of view), to keep the test quick.
    Lens lens = Lens::paper();
    lens.width = 320;
    lens.height = 256;
    lens.r_pp *= 4;
    View view;
    view.width = 320;
    view.height = 256;
    const cv::Mat rgb = render_fisheye(lens);
    const cv::Mat raw = mosaic(rgb, BayerPattern::BGGR);
    const auto fused = make_preprocessor(lens, view, BayerPattern::BGGR, DemosaicMethod::Bilinear, PreprocessPath::Fused);
    const auto separate = make_preprocessor(lens, view, BayerPattern::BGGR, DemosaicMethod::Bilinear, PreprocessPath::Separate);
    const cv::Mat a = fused(raw), b = separate(raw);
    QCOMPARE(a.size(), cv::Size(320, 256));
    QCOMPARE(a.type(), CV_8UC3);
    double max_diff = 0;
    cv::minMaxLoc(cv::abs(a - b) + cv::abs(b - a), nullptr, &max_diff);
    QVERIFY2(max_diff <= 2, qPrintable(QString::number(max_diff)));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                             make_preprocessor(lens, view, BayerPattern::BGGR, DemosaicMethod::MalvarHeCutler, PreprocessPath::Fused));
    // The whole pipeline with the real stage and OpenCV's HOG people detector.
    const auto r = run_pipeline([&](std::size_t i) { return i < 3 ? std::optional<cv::Mat>(raw) : std::nullopt; }, fused,
                                hog_people_detector(1.0), {}, bs::CancelToken{});
    QCOMPARE(r.processed, std::size_t{3});
    QCOMPARE(r.stage("detection")->summary.n, std::size_t{3});
  }

  void ssd_output_parsing() {
    // Two rows of [image, class, score, x0, y0, x1, y1]: one above the threshold, one below.
    const float rows[] = {0, 15, 0.9f, 0.1f, 0.2f, 0.5f, 0.8f, 0, 15, 0.3f, 0, 0, 1, 1};
    const int dims[] = {1, 1, 2, 7};
    const cv::Mat out(4, dims, CV_32F, const_cast<float*>(rows));
    const auto dets = parse_ssd_output(out, cv::Size(200, 100), 0.5f);
    QCOMPARE(dets.size(), std::size_t{1});
    QCOMPARE(dets[0].box, cv::Rect(cv::Point(20, 20), cv::Point(100, 80)));
    QCOMPARE(dets[0].class_id, 15);
    const cv::Mat drawn = draw_detections(cv::Mat(100, 200, CV_8UC3, cv::Scalar::all(0)), dets);
    QVERIFY(drawn.at<cv::Vec3b>(20, 50)[1] == 255);  // the box's top edge is green
  }
};

QTEST_APPLESS_MAIN(TestPipeline)
#include "test_pipeline.moc"
