// SPDX-License-Identifier: GPL-3.0-or-later
// The concurrent pipeline: bounded queues under both policies, ordering, timing counts, cancellation within a
// frame, the real preprocessing paths on the paper's lens, and the detectors' output handling.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>

#include <QTest>

#include "vision/frames/synthetic.h"
#include "vision/pipeline/bounded_queue.h"
#include "vision/pipeline/detector.h"
#include "vision/pipeline/pipeline.h"
#include "vision/reproject/preprocess.h"

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
    const auto r =
        run_pipeline(small_frames(40), to_bgr(), det, {.max_frames = 100, .queue_capacity = 2}, bs::CancelToken{});
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
    const auto r =
        run_pipeline(small_frames(200), to_bgr(), slow,
                     {.max_frames = 200, .queue_capacity = 1, .policy = QueuePolicy::DropOldest}, bs::CancelToken{});
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
    const auto r = run_pipeline(small_frames(100000), to_bgr(), det,
                                {.max_frames = 100000, .queue_capacity = 2, .detection_workers = 1}, cancel);
    QVERIFY(r.cancelled);
    QCOMPARE(calls.load(), 3);  // no detection after the one that cancelled
    QVERIFY(r.captured < 100);  // the capture stopped too, within the queues' slack
  }

  void several_workers_detect_every_frame_once() {
    // Frame i carries its index in its first two pixels; the detector reports it back as the score.
    constexpr int n = 300;
    const FrameSource numbered = [](std::size_t i) -> std::optional<cv::Mat> {
      if (static_cast<int>(i) >= n) return std::nullopt;
      cv::Mat m(8, 8, CV_8UC1, cv::Scalar(0));
      m.at<uchar>(0, 0) = static_cast<uchar>(i % 256);
      m.at<uchar>(0, 1) = static_cast<uchar>(i / 256);
      return m;
    };
    const auto index_of = [](const cv::Mat& bgr) {
      return bgr.at<cv::Vec3b>(0, 0)[0] + 256 * bgr.at<cv::Vec3b>(0, 1)[0];
    };
    std::mutex mutex;
    std::vector<int> seen;
    std::atomic<int> running{0}, most_running{0};
    Detector det = [&](const cv::Mat& bgr) {
      const int now = ++running;
      for (int m = most_running; now > m && !most_running.compare_exchange_weak(m, now);) {
      }
      std::this_thread::sleep_for(std::chrono::microseconds(300));  // long enough for the workers to overlap
      --running;
      std::lock_guard lock(mutex);
      seen.push_back(index_of(bgr));
      return std::vector<Detection>{{cv::Rect(0, 0, 2, 2), static_cast<double>(seen.back()), -1}};
    };
    const auto r = run_pipeline(numbered, to_bgr(), det,
                                {.max_frames = 1000, .queue_capacity = 4, .detection_workers = 4}, bs::CancelToken{});
    QCOMPARE(r.detection_workers, std::size_t{4});
    QCOMPARE(r.captured, std::size_t{n});
    QCOMPARE(r.processed, std::size_t{n});
    QCOMPARE(r.dropped, std::size_t{0});
    std::sort(seen.begin(), seen.end());
    QCOMPARE(seen.size(), std::size_t{n});
    for (int i = 0; i < n; ++i) QCOMPARE(seen[static_cast<std::size_t>(i)], i);  // each frame exactly once
    for (const auto& s : r.stages) QCOMPARE(s.summary.n, std::size_t{n});
    QVERIFY2(most_running.load() > 1, "the detection workers never overlapped");
    QVERIFY(most_running.load() <= 4);
    // The latest frame by index, whichever worker finished last.
    QCOMPARE(r.last_index, std::size_t{n - 1});
    QCOMPARE(r.last_detections.at(0).score, static_cast<double>(n - 1));
    QCOMPARE(index_of(r.last_output), n - 1);
  }

  void cancel_with_several_workers_starts_no_new_frame() {
    // After the cancel no worker starts a frame: only the ones already in flight (at most workers - 1) finish.
    constexpr std::size_t kWorkers = 4;
    bs::CancelToken cancel;
    std::atomic<int> calls{0};
    Detector det = [&](const cv::Mat&) {
      if (++calls == 10) cancel.cancel();
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      return std::vector<Detection>{};
    };
    const auto r = run_pipeline(small_frames(100000), to_bgr(), det,
                                {.max_frames = 100000, .queue_capacity = 2, .detection_workers = kWorkers}, cancel);
    QVERIFY(r.cancelled);
    QVERIFY2(calls.load() >= 10 && calls.load() <= 10 + static_cast<int>(kWorkers) - 1,
             qPrintable(QString::number(calls)));
    QCOMPARE(r.processed, static_cast<std::size_t>(calls.load()));
    QCOMPARE(r.stage("detection")->summary.n, r.processed);
    QVERIFY(r.captured < 100);
  }

  void drop_oldest_with_several_workers() {
    Detector slow = [](const cv::Mat&) {
      std::this_thread::sleep_for(std::chrono::milliseconds(3));
      return std::vector<Detection>{};
    };
    const auto r = run_pipeline(
        small_frames(300), to_bgr(), slow,
        {.max_frames = 300, .queue_capacity = 1, .policy = QueuePolicy::DropOldest, .detection_workers = 2},
        bs::CancelToken{});
    QCOMPARE(r.captured, std::size_t{300});
    QVERIFY(r.dropped > 0);
    QCOMPARE(r.processed + r.dropped, r.captured);
    QCOMPARE(r.stage("detection")->summary.n, r.processed);
  }

  void bad_worker_counts_are_rejected() {
    const Detector none_found = [](const cv::Mat&) { return std::vector<Detection>{}; };
    for (std::size_t w : {std::size_t{0}, kMaxDetectionWorkers + 1})
      QVERIFY_THROWS_EXCEPTION(std::invalid_argument, run_pipeline(small_frames(3), to_bgr(), none_found,
                                                                   {.detection_workers = w}, bs::CancelToken{}));
    QVERIFY(default_detection_workers() >= 1);
    QCOMPARE(PipelineConfig{}.detection_workers, default_detection_workers());
  }

  void detect_scale_maps_boxes_back() {
    // A stub that finds one box at a known place in the image it is given, and records that image's size.
    cv::Size given;
    const Detector stub = [&](const cv::Mat& img) {
      given = img.size();
      return std::vector<Detection>{{cv::Rect(10, 20, 30, 40), 1.5, 3},
                                    {cv::Rect(img.cols - 5, img.rows - 5, 20, 20), 0.5, 3}};  // past the corner
    };
    const cv::Mat frame(320, 400, CV_8UC3, cv::Scalar::all(7));
    const auto quarter = scaled_detector(stub, 0.25)(frame);
    QCOMPARE(given, cv::Size(100, 80));
    QCOMPARE(quarter.size(), std::size_t{2});
    QCOMPARE(quarter[0].box, cv::Rect(40, 80, 120, 160));
    QCOMPARE(quarter[0].score, 1.5);
    QCOMPARE(quarter[0].class_id, 3);
    QCOMPARE(quarter[1].box, cv::Rect(380, 300, 20, 20));  // mapped back, then clipped to the full frame
    const auto full = scaled_detector(stub, 1.0)(frame);
    QCOMPARE(given, cv::Size(400, 320));
    QCOMPARE(full[0].box, cv::Rect(10, 20, 30, 40));
    for (double bad : {0.0, -0.5, 1.01, std::nan("")})
      QVERIFY_THROWS_EXCEPTION(std::invalid_argument, scaled_detector(stub, bad));
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, hog_people_detector(0));
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
    const auto fused =
        make_preprocessor(lens, view, BayerPattern::BGGR, DemosaicMethod::Bilinear, PreprocessPath::Fused);
    const auto separate =
        make_preprocessor(lens, view, BayerPattern::BGGR, DemosaicMethod::Bilinear, PreprocessPath::Separate);
    const cv::Mat a = fused(raw), b = separate(raw);
    QCOMPARE(a.size(), cv::Size(320, 256));
    QCOMPARE(a.type(), CV_8UC3);
    double max_diff = 0;
    cv::minMaxLoc(cv::abs(a - b) + cv::abs(b - a), nullptr, &max_diff);
    QVERIFY2(max_diff <= 2, qPrintable(QString::number(max_diff)));
    QVERIFY_THROWS_EXCEPTION(
        std::invalid_argument,
        make_preprocessor(lens, view, BayerPattern::BGGR, DemosaicMethod::MalvarHeCutler, PreprocessPath::Fused));
    // The whole pipeline with the real stage and OpenCV's HOG people detector.
    const auto r = run_pipeline([&](std::size_t i) { return i < 3 ? std::optional<cv::Mat>(raw) : std::nullopt; },
                                fused, hog_people_detector(1.0), {}, bs::CancelToken{});
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
