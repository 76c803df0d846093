// SPDX-License-Identifier: GPL-3.0-or-later
// Line proposals (issue #20 part 3, "or accepts long edges BenchScope proposes") on the synthetic room with known
// truth: how many of the room's grid lines they find (recall), how many of them are straight in the world
// (precision), that curves drawn into the frame are not proposed, and that the line fit fed with them from a
// perturbed lens lands on the truth.
#include <QTest>
#include <cmath>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "../../../support/core_ray_projection.h"
#include "../../../support/room_lens.h"
#include "vision/frames/synthetic_room.h"
#include "vision/lens/edge_proposals.h"
#include "vision/lens/fisheye_opencv.h"
#include "vision/lens/line_fit.h"

using namespace bs::vision;

namespace {

constexpr double kPi = 3.14159265358979323846;
// Straightness under the true lens below which a proposal counts as a line of the world: the straight ones measure
// 0.02 to 0.11 px here, two stripes meeting at a room's corner 0.25 px and more.
constexpr double kStraightPx = 0.2;

double polyline_distance(const PickedLine& line, const cv::Point2d& q) {
  double best = 1e300;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) {
    const cv::Point2d a = line[i], d = line[i + 1] - line[i];
    const double t = std::clamp((q - a).dot(d) / std::max(d.dot(d), 1e-12), 0.0, 1.0);
    best = std::min(best, cv::norm(a + t * d - q));
  }
  return best;
}

// Every grid line of the room (synthetic_room.h: walls x = 2.1 / -1.7, y = 1.6 / -1.9, floor z = -1.2, ceiling
// 1.5, lines every 0.5 m): room_grid_lines' wall lines plus the walls' z = 0 line and the floor's and ceiling's.
std::vector<Segment3d> all_grid_lines(double yaw) {
  auto lines = room_grid_lines(yaw);
  std::vector<Segment3d> more;
  for (double z : {-1.2, 1.5}) {
    for (double x = -1.5; x <= 2.0 + 1e-9; x += 0.5) more.push_back({{x, -1.9, z}, {x, 1.6, z}});
    for (double y = -1.5; y <= 1.5 + 1e-9; y += 0.5) more.push_back({{-1.7, y, z}, {2.1, y, z}});
  }
  more.push_back({{2.1, -1.9, 0}, {2.1, 1.6, 0}});
  more.push_back({{-1.7, -1.9, 0}, {-1.7, 1.6, 0}});
  more.push_back({{-1.7, 1.6, 0}, {2.1, 1.6, 0}});
  more.push_back({{-1.7, -1.9, 0}, {2.1, -1.9, 0}});
  const double c = std::cos(yaw), s = std::sin(yaw);  // room -> camera, as room_grid_lines
  for (const auto& m : more)
    lines.push_back({{c * m.a[0] + s * m.a[1], -s * m.a[0] + c * m.a[1], m.a[2]},
                     {c * m.b[0] + s * m.b[1], -s * m.b[0] + c * m.b[1], m.b[2]}});
  return lines;
}

// The grid lines' visible stretches in the image: samples every ~2 px of image, kept where the ray sees the line's
// own dark stripe (not a dark object in front of it) and the point is inside the disc by the margin.
struct TruthLine {
  std::vector<cv::Point2d> px;
};
std::vector<TruthLine> visible_grid_lines(const Lens& lens, std::uint64_t seed, double margin) {
  const double yaw = room_yaw(seed);
  const double rim = *lens.radius(lens.fov_deg * kPi / 360);
  std::vector<TruthLine> out;
  for (const auto& seg : all_grid_lines(yaw)) {
    TruthLine t;
    for (int i = 0; i <= 2000; ++i) {
      const cv::Vec3d p = seg.a + (seg.b - seg.a) * (i / 2000.0);
      const auto q = bs::test::project_ray(lens, p);
      if (!q || cv::norm(*q - lens.centre()) > rim - margin) continue;
      const cv::Vec3d c = room_colour(p, yaw);
      if (std::abs(c[0] - 0.06) > 1e-9 || std::abs(c[2] - 0.06) > 1e-9) continue;  // hidden by an object
      if (!t.px.empty() && cv::norm(*q - t.px.back()) < 2) continue;
      t.px.push_back(*q);
    }
    out.push_back(std::move(t));
  }
  return out;
}

struct Scores {
  int truth_lines = 0, found = 0;  // grid lines with >= 100 px visible; those >= half covered by proposals
  int proposals = 0, straight = 0, on_grid = 0;
  double recall() const { return truth_lines ? static_cast<double>(found) / truth_lines : 0; }
  double precision() const { return proposals ? static_cast<double>(straight) / proposals : 0; }
  double grid_precision() const { return proposals ? static_cast<double>(on_grid) / proposals : 0; }
};

// Recall: a grid line with 100 px or more visible counts as found when proposals run within 4 px of half its
// visible samples or more (a dark stripe's two edges lie ~2 px either side of its centre). Precision: a proposal
// is right when it is straight in the world, i.e. straight under the true lens (RMS < kStraightPx); "on grid" when
// 80 % of its points lie within 4 px of one grid line (the rest are the objects' and the room's own edges).
Scores score(const Lens& truth, const std::vector<PickedLine>& proposals, std::uint64_t seed) {
  Scores s;
  const auto truth_lines = visible_grid_lines(truth, seed, 8);
  for (const auto& t : truth_lines) {
    if (t.px.size() < 50) continue;
    ++s.truth_lines;
    int covered = 0;
    for (const auto& q : t.px) {
      for (const auto& p : proposals)
        if (polyline_distance(p, q) < 4) {
          ++covered;
          break;
        }
    }
    s.found += 2 * covered >= static_cast<int>(t.px.size());
  }
  for (const auto& p : proposals) {
    ++s.proposals;
    s.straight += line_straightness(truth, {p}).rms_px < kStraightPx;
    for (const auto& t : truth_lines) {
      if (t.px.size() < 2) continue;
      int near = 0;
      for (const auto& q : p) near += polyline_distance(t.px, q) < 4;
      if (5 * near >= 4 * static_cast<int>(p.size())) {
        ++s.on_grid;
        break;
      }
    }
  }
  return s;
}

// The room capture with curves drawn in (circles and an ellipse arc, dark on the walls): never straight.
cv::Mat room_with_curves(const Lens& truth, const RoomOptions& room) {
  cv::Mat img = render_room_fisheye(truth, room);
  cv::circle(img, {420, 380}, 70, cv::Scalar(20, 20, 20), 4, cv::LINE_AA);
  cv::circle(img, {880, 640}, 110, cv::Scalar(20, 20, 20), 4, cv::LINE_AA);
  cv::ellipse(img, {700, 300}, {160, 60}, 20, 0, 180, cv::Scalar(20, 20, 20), 4, cv::LINE_AA);
  return img;
}

// The lens the stray-edge test works under: a few pixels off, as when proposing from a first guess.
Lens start_lens_for_stray(const Lens& truth) { return bs::test::circle_fit_start(truth, 3.0, -2.0); }

}  // namespace

double centre_error(const Lens& a, const Lens& b) { return std::hypot(a.cx - b.cx, a.cy - b.cy); }
double r_pp_error(const Lens& a, const Lens& b) { return std::abs(a.r_pp / b.r_pp - 1); }

class TestEdgeProposals : public QObject {
  Q_OBJECT
 private slots:
  void proposals_on_the_room() {
    const Lens truth = bs::test::room_truth_lens();
    const RoomOptions room{.vignetting = 0.3, .noise = 0.005, .seed = 5};
    const cv::Mat img = room_with_curves(truth, room);
    const Lens start = bs::test::circle_fit_start(truth, 5.0, -4.0);
    const auto props = propose_lines(img, start);
    const auto lines = proposal_points(props);
    const Scores s = score(truth, lines, room.seed);
    qInfo("%d edge px, %d chains, %d pieces -> %zu lines (%d too bent, %d short or rough)", props.edge_pixels,
          props.chains, props.pieces, props.lines.size(), props.rejected_bent, props.rejected_short);
    qInfo("recall %d/%d = %.2f; precision %d/%d = %.2f (straight in the world), %.2f on a grid line", s.found,
          s.truth_lines, s.recall(), s.straight, s.proposals, s.precision(), s.grid_precision());
    if (qEnvironmentVariableIsSet("EDGE_DEBUG")) {
      cv::Mat dbg = img.clone();
      for (const auto& l : props.lines) {
        std::vector<cv::Point> poly;
        for (const auto& q : l.points) poly.emplace_back(cvRound(q.x), cvRound(q.y));
        const bool ok = line_straightness(truth, {l.points}).rms_px < kStraightPx;
        cv::polylines(dbg, poly, false, ok ? cv::Scalar(0, 200, 0) : cv::Scalar(0, 0, 255), 2);
      }
      cv::imwrite("/tmp/edges_debug.png", dbg);
    }
    // Measured (seed 5, start centre 6.4 px off, equidistant against the Kannala-Brandt truth): 80 lines (the
    // cap, the longest), recall 38/51 = 0.75 (the grid lines missed are short stretches near the rim, or lost to
    // the cap), precision 73/80 = 0.91, 0.81 on a grid line (the rest: the objects' and the room's own edges, all
    // straight too). The 7 not straight in the world are stripes running on round a room's corner (one plane that
    // misses the camera: a kink of a fraction of a pixel, which the bend the wrong lens puts in every line hides
    // until the lens is fitted); the fit's line rejection takes them out (next test).
    QCOMPARE(static_cast<int>(props.lines.size()), 80);
    QVERIFY(s.recall() >= 0.7);
    QVERIFY(s.precision() >= 0.85);
    // Every proposal is long, smooth and points along it come in order.
    for (const auto& l : props.lines) {
      QVERIFY(l.length_px >= 80);
      QVERIFY(l.rms_px <= 0.5);
      QVERIFY(l.points.size() >= 3);
      for (std::size_t i = 1; i < l.points.size(); ++i) QVERIFY(cv::norm(l.points[i] - l.points[i - 1]) < 100);
    }
    // The curves drawn in are never proposed: no proposal runs along them.
    const auto on_curve = [](const cv::Point2d& p) {
      return std::abs(cv::norm(p - cv::Point2d(420, 380)) - 70) < 4 ||
             std::abs(cv::norm(p - cv::Point2d(880, 640)) - 110) < 4;
    };
    for (const auto& l : props.lines) {
      int near = 0;
      for (const auto& p : l.points) near += on_curve(p);
      QVERIFY2(near < 4, qPrintable(QString("a proposal runs along a drawn circle (%1 points)").arg(near)));
    }
  }
  void fit_from_proposals_recovers_the_lens() {
    // The proposals, found under a perturbed lens, fed to the line fit (rim held at the circle fit's 600 px, lines
    // rejected at 3x the median's RMS): centre within 1 px and r_pp within 0.5 %. Measured: the start is 6.40 px
    // (seed 5) and 5.00 px (seed 9) off, r_pp 7.31 % (equidistant with the right rim against the truth's bending
    // r(theta)); after, seed 5: 0.166 px, 0.181 % (7 lines rejected, all 7 not straight in the world); seed 9
    // (noise 0.01): 0.098 px, 0.088 % (6 rejected, all not straight). Without the rejection: 2.65 px, 0.91 % and
    // 0.69 px, 0.23 %: the kinked lines pull the fit, which is why the rejection is there.
    struct Case {
      std::uint64_t seed;
      double noise, dx, dy;
    };
    for (const Case c : {Case{5, 0.005, 5.0, -4.0}, Case{9, 0.01, -4.0, 3.0}}) {
      const Lens truth = bs::test::room_truth_lens();
      RoomOptions room;
      room.seed = c.seed;
      room.vignetting = 0.3;
      room.noise = c.noise;
      const cv::Mat img = room_with_curves(truth, room);
      const Lens start = bs::test::circle_fit_start(truth, c.dx, c.dy);
      const auto lines = proposal_points(propose_lines(img, start));
      LineFitOptions o;
      o.circle_radius_px = 600;
      const auto plain = fit_lens_to_lines(start, lines, o);
      o.reject_lines = 3;
      const auto fit = fit_lens_to_lines(start, lines, o);
      int bad_kept = 0, bad_rejected = 0;
      for (std::size_t i = 0; i < lines.size(); ++i) {
        const bool bad = line_straightness(truth, {lines[i]}).rms_px >= kStraightPx;
        const bool rejected = std::find(fit.rejected_lines.begin(), fit.rejected_lines.end(), static_cast<int>(i)) !=
                              fit.rejected_lines.end();
        bad_kept += bad && !rejected;
        bad_rejected += bad && rejected;
      }
      qInfo(
          "seed %d: %zu lines, %zu rejected (%d of them not straight in the world, %d such kept); RMS %.3f -> "
          "%.3f px; centre error %.2f -> %.3f px, r_pp error %.2f -> %.3f %% (no rejection: %.3f px, "
          "%.3f %%)",
          static_cast<int>(c.seed), lines.size(), fit.rejected_lines.size(), bad_rejected, bad_kept, fit.before.rms_px,
          fit.after.rms_px, centre_error(start, truth), centre_error(fit.lens, truth), 100 * r_pp_error(start, truth),
          100 * r_pp_error(fit.lens, truth), centre_error(plain.lens, truth), 100 * r_pp_error(plain.lens, truth));
      QVERIFY(centre_error(fit.lens, truth) < 1.0);
      QVERIFY(r_pp_error(fit.lens, truth) < 0.005);
      QVERIFY(fit.lens.calibration.detail.find("left out") != std::string::npos);
    }
  }
  void one_stray_edge_does_not_bend_a_line() {
    // A grid line's true image points, every 4 px, with 0.1 px noise, and a stray edge running off it for 8 points
    // (a door handle touching a door frame): the second pass drops the stray points and nothing else.
    const Lens truth = bs::test::room_truth_lens();
    cv::RNG rng(7);
    PickedLine line;
    for (const auto& seg : room_grid_lines(room_yaw(5))) {  // the longest in view
      PickedLine l;
      for (int i = 0; i <= 400; ++i) {
        const auto p = bs::test::project_ray(truth, seg.a + (seg.b - seg.a) * (i / 400.0));
        if (!p || cv::norm(*p - truth.centre()) > 560) continue;
        if (!l.empty() && cv::norm(*p - l.back()) < 4) continue;
        l.emplace_back(p->x + rng.gaussian(0.1), p->y + rng.gaussian(0.1));
      }
      if (l.size() > line.size()) line = l;
    }
    QVERIFY(line.size() > 60);
    PickedLine bent = line;
    const std::size_t at = bent.size() / 2;
    const cv::Point2d along = bent[at + 1] - bent[at];
    const cv::Point2d across = cv::Point2d(-along.y, along.x) * (1 / cv::norm(along));
    for (std::size_t k = 0; k < 8; ++k) bent[at + k] += across * (1.0 + 0.5 * static_cast<double>(k));
    int dropped = 0;
    const PickedLine kept = drop_line_outliers(start_lens_for_stray(truth), bent, 0.8, &dropped);
    const double before = line_straightness(truth, {bent}).rms_px, after = line_straightness(truth, {kept}).rms_px;
    qInfo("stray edge: %zu points, %d dropped; straightness under the truth %.3f -> %.3f px", bent.size(), dropped,
          before, after);
    QCOMPARE(dropped, 8);
    QVERIFY(after < 0.15);
    QVERIFY(before > 3 * after);
  }
  void proposing_twice_adds_nothing_and_bad_input_throws() {
    const Lens truth = bs::test::room_truth_lens();
    const cv::Mat img = render_room_fisheye(truth);
    const auto lines = proposal_points(propose_lines(img, truth));
    QVERIFY(lines.size() > 20);
    QVERIFY(lines_not_in(lines, lines).empty());
    QCOMPARE(lines_not_in(lines, {}).size(), lines.size());
    std::vector<PickedLine> half(lines.begin(), lines.begin() + static_cast<long>(lines.size() / 2));
    QCOMPARE(lines_not_in(lines, half).size(), lines.size() - half.size());
    // 16-bit and gray frames work too; empty ones and bad options throw.
    cv::Mat gray16;
    cv::cvtColor(img, gray16, cv::COLOR_BGR2GRAY);
    gray16.convertTo(gray16, CV_16U, 257);
    QVERIFY(propose_lines(gray16, truth).lines.size() > 20);
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, propose_lines(cv::Mat(), truth));
    LineProposalOptions bad;
    bad.inlier_px = 0;
    QVERIFY_THROWS_EXCEPTION(std::invalid_argument, propose_lines(img, truth, bad));
    // A blank frame proposes nothing.
    QVERIFY(propose_lines(cv::Mat(truth.height, truth.width, CV_8UC3, cv::Scalar::all(90)), truth).lines.empty());
  }
};

QTEST_GUILESS_MAIN(TestEdgeProposals)
#include "test_edge_proposals.moc"
