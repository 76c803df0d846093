// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/lens/edge_proposals.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include <opencv2/imgproc.hpp>

namespace bs::vision {
namespace {

// An edge point with its ray under the current lens and the ray's derivatives per source pixel, so that a plane's
// distance n.v - d converts to source pixels to first order (as line_fit.cpp's plane_distances does).
// `g` is the unit image gradient there (towards the brighter side), for the edge's polarity.
struct RayPoint {
  cv::Point2d px;
  cv::Vec3d v, vx, vy;
  cv::Point2d g;
};

// The plane n.v = d of a line's rays (|n| = 1, d >= 0): d = 0 is a great circle (straight in the world).
struct Plane {
  cv::Vec3d n{0, 0, 1};
  double d = 0;
};

bool ray_point(const Lens& lens, const cv::Point2d& p, RayPoint& out, cv::Point2d g = {}) {
  constexpr double h = 0.05;
  const auto v = pixel_to_ray(lens, p);
  const auto a = pixel_to_ray(lens, p + cv::Point2d(h, 0));
  const auto b = pixel_to_ray(lens, p + cv::Point2d(0, h));
  if (!v || !a || !b) return false;
  out = {p, *v, (*a - *v) / h, (*b - *v) / h, g};
  return true;
}

// Which side of the plane the brighter side lies on: +1, -1, 0 without a gradient. The two edges of a dark stripe
// have opposite signs, so a line that jumps from one to the other across a crossing shows both.
int polarity(const Plane& pl, const RayPoint& r) {
  const double s = pl.n.dot(r.vx * r.g.x + r.vy * r.g.y);
  return s > 0 ? 1 : s < 0 ? -1 : 0;
}

double px_distance(const Plane& pl, const RayPoint& r) {
  const double g = std::hypot(pl.n.dot(r.vx), pl.n.dot(r.vy));
  return (pl.n.dot(r.v) - pl.d) / std::max(g, 1e-12);
}

// Least squares plane through the rays (small circle: free d; great circle: d = 0), each ray weighted by the
// square of its pixels per unit of plane distance under `prior` (so that the sum is of squared pixel distances).
template <typename Index>
Plane fit_plane(const std::vector<RayPoint>& pts, const Index& idx, bool great, const Plane* prior = nullptr) {
  cv::Vec3d m(0, 0, 0);
  double wsum = 0;
  std::vector<double> w;
  w.reserve(idx.size());
  for (const auto i : idx) {
    double wi = 1;
    if (prior) {
      const double g = std::hypot(prior->n.dot(pts[i].vx), prior->n.dot(pts[i].vy));
      wi = 1 / std::max(g * g, 1e-18);
    }
    w.push_back(wi);
    m += wi * pts[i].v;
    wsum += wi;
  }
  if (great || wsum <= 0)
    m = cv::Vec3d(0, 0, 0);
  else
    m *= 1 / wsum;
  cv::Matx33d c = cv::Matx33d::zeros();
  std::size_t k = 0;
  for (const auto i : idx) {
    const cv::Vec3d d = pts[i].v - m;
    c += w[k++] * (d * d.t());
  }
  cv::Mat values, vectors;
  cv::eigen(cv::Mat(c), values, vectors);  // descending: the last row is the normal
  Plane pl;
  pl.n = cv::Vec3d(vectors.at<double>(2, 0), vectors.at<double>(2, 1), vectors.at<double>(2, 2));
  pl.d = great ? 0 : pl.n.dot(m);
  if (pl.d < 0) pl.n = -pl.n, pl.d = -pl.d;
  return pl;
}

std::vector<std::size_t> all_of(const std::vector<RayPoint>& pts) {
  std::vector<std::size_t> idx(pts.size());
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  return idx;
}

// Robust refit of one line's points (the second pass): least squares, then points beyond max(inlier_px, 3 robust
// sigmas) dropped and the rest refitted, until none goes. Returns the kept indices and their plane.
std::vector<std::size_t> robust_keep(const std::vector<RayPoint>& pts, double inlier_px, Plane& pl) {
  std::vector<std::size_t> keep = all_of(pts);
  if (pts.size() < 3) return keep;
  pl = fit_plane(pts, keep, false);
  pl = fit_plane(pts, keep, false, &pl);
  for (int round = 0; round < 10; ++round) {
    std::vector<double> r;
    r.reserve(keep.size());
    for (const auto i : keep) r.push_back(std::abs(px_distance(pl, pts[i])));
    std::vector<double> sorted = r;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    const double sigma = 1.4826 * sorted[sorted.size() / 2];
    const double thr = std::max(inlier_px, 3 * sigma);
    std::vector<std::size_t> next;
    for (std::size_t k = 0; k < keep.size(); ++k)
      if (r[k] <= thr) next.push_back(keep[k]);
    if (next.size() == keep.size() || next.size() < 3) break;
    keep.swap(next);
    pl = fit_plane(pts, keep, false, &pl);
  }
  return keep;
}

double arc_length(const std::vector<RayPoint>& pts, std::size_t lo, std::size_t hi) {
  double s = 0;
  for (std::size_t i = lo + 1; i < hi; ++i) s += cv::norm(pts[i].px - pts[i - 1].px);
  return s;
}

// One straight piece: ordered ray points and their plane.
struct Piece {
  std::vector<RayPoint> pts;
  Plane plane, great;
  double length = 0;
};

Piece make_piece(std::vector<RayPoint> pts) {
  Piece p;
  p.pts = std::move(pts);
  const auto idx = all_of(p.pts);
  p.plane = fit_plane(p.pts, idx, false);
  p.plane = fit_plane(p.pts, idx, false, &p.plane);
  p.great = fit_plane(p.pts, idx, true);
  p.length = arc_length(p.pts, 0, p.pts.size());
  return p;
}

constexpr double kMinPiecePx = 15;  // pieces shorter than this carry too little to merge reliably

// Splits pts[lo, hi) into pieces that each lie on one plane: RANSAC (3-point planes, points drawn from the three
// thirds of the range) for the plane with the most inliers, least squares on them, then the longest run of
// inliers (gaps of a few outliers bridged) is a piece and the parts before and after are tried again.
void split_straight(const std::vector<RayPoint>& pts, std::size_t lo, std::size_t hi, double inlier_px, cv::RNG& rng,
                    std::vector<Piece>& out) {
  if (hi - lo < 8 || arc_length(pts, lo, hi) < kMinPiecePx) return;
  const std::size_t n = hi - lo;
  const auto count_inliers = [&](const Plane& pl) {
    int c = 0;
    for (std::size_t i = lo; i < hi; ++i) c += std::abs(px_distance(pl, pts[i])) < inlier_px;
    return c;
  };
  Plane best;
  int best_count = -1;
  const int third = static_cast<int>(n / 3);
  for (int it = 0; it < 48; ++it) {
    const std::size_t a = lo + static_cast<std::size_t>(rng.uniform(0, third));
    const std::size_t b = lo + static_cast<std::size_t>(third + rng.uniform(0, third));
    const std::size_t c = lo + static_cast<std::size_t>(2 * third + rng.uniform(0, static_cast<int>(n) - 2 * third));
    const cv::Vec3d nrm = (pts[b].v - pts[a].v).cross(pts[c].v - pts[a].v);
    const double len = cv::norm(nrm);
    if (len < 1e-15) continue;
    Plane pl;
    pl.n = nrm / len;
    pl.d = pl.n.dot(pts[a].v);
    if (pl.d < 0) pl.n = -pl.n, pl.d = -pl.d;
    const int count = count_inliers(pl);
    if (count > best_count) best_count = count, best = pl;
  }
  if (best_count < 3) return;
  std::vector<char> in(n);
  for (int round = 0; round < 3; ++round) {
    std::vector<std::size_t> idx;
    for (std::size_t i = lo; i < hi; ++i)
      if (std::abs(px_distance(best, pts[i])) < inlier_px) idx.push_back(i);
    if (idx.size() < 3) return;
    best = fit_plane(pts, idx, false, &best);
  }
  for (std::size_t i = lo; i < hi; ++i) in[i - lo] = std::abs(px_distance(best, pts[i])) < inlier_px;
  // The longest run of inliers by arc length, bridging up to 3 consecutive outliers.
  std::size_t run_lo = 0, run_hi = 0, cur_lo = 0;
  double best_len = -1;
  int outliers = 0;
  std::size_t last_in = 0;
  bool open = false;
  const auto close_run = [&](std::size_t end) {
    const double len = arc_length(pts, lo + cur_lo, lo + end);
    if (len > best_len) best_len = len, run_lo = cur_lo, run_hi = end;
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (in[i]) {
      if (!open) open = true, cur_lo = i;
      last_in = i;
      outliers = 0;
    } else if (open && ++outliers > 3) {
      close_run(last_in + 1);
      open = false;
      outliers = 0;
    }
  }
  if (open) close_run(last_in + 1);
  if (best_len < 0) return;
  std::vector<RayPoint> piece;
  for (std::size_t i = run_lo; i < run_hi; ++i)
    if (in[i]) piece.push_back(pts[lo + i]);
  if (piece.size() >= 8 && best_len >= kMinPiecePx) out.push_back(make_piece(std::move(piece)));
  split_straight(pts, lo, lo + run_lo, inlier_px, rng, out);
  split_straight(pts, lo + run_hi, hi, inlier_px, rng, out);
}

// Orders the points of a line along its plane (angle about the plane's normal from the mean ray).
void order_along(std::vector<RayPoint>& pts, const Plane& pl) {
  cv::Vec3d m(0, 0, 0);
  for (const auto& p : pts) m += p.v;
  cv::Vec3d e1 = m - pl.n.dot(m) * pl.n;
  if (cv::norm(e1) < 1e-12) return;
  e1 /= cv::norm(e1);
  const cv::Vec3d e2 = pl.n.cross(e1);
  std::vector<std::pair<double, std::size_t>> key(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) key[i] = {std::atan2(pts[i].v.dot(e2), pts[i].v.dot(e1)), i};
  std::sort(key.begin(), key.end());
  std::vector<RayPoint> sorted;
  sorted.reserve(pts.size());
  for (const auto& k : key) sorted.push_back(pts[k.second]);
  pts.swap(sorted);
}

double min_distance_to(const std::vector<RayPoint>& pts, const cv::Point2d& q) {
  double best = 1e300;
  for (const auto& p : pts) best = std::min(best, cv::norm(p.px - q));
  return best;
}

// Whether b continues a (same plane, within the gap): the union must fit one small circle to the edge noise.
bool try_merge(Piece& a, const Piece& b, const LineProposalOptions& o) {
  // Cheap tests first: b's ends and middle near a's great circle (allowing the bend), a gap no longer than allowed.
  const double near = o.max_bend_px + 2;
  for (const RayPoint* p : {&b.pts.front(), &b.pts[b.pts.size() / 2], &b.pts.back()})
    if (std::abs(px_distance(a.great, *p)) > near) return false;
  for (const RayPoint* p : {&a.pts.front(), &a.pts[a.pts.size() / 2], &a.pts.back()})
    if (std::abs(px_distance(b.great, *p)) > near) return false;
  const double gap = std::min({min_distance_to(a.pts, b.pts.front().px), min_distance_to(a.pts, b.pts.back().px),
                               min_distance_to(b.pts, a.pts.front().px), min_distance_to(b.pts, a.pts.back().px)});
  if (gap > o.max_gap_px) return false;
  std::vector<RayPoint> all = a.pts;
  all.insert(all.end(), b.pts.begin(), b.pts.end());
  const auto idx = all_of(all);
  Plane pl = fit_plane(all, idx, false);
  pl = fit_plane(all, idx, false, &pl);
  double ss = 0;
  int far = 0, plus = 0, minus = 0;
  for (const auto& p : all) {
    const double d = px_distance(pl, p);
    ss += d * d;
    far += std::abs(d) > 2 * o.inlier_px;
    const int s = polarity(pl, p);
    plus += s > 0;
    minus += s < 0;
  }
  const int limit = static_cast<int>(all.size() / 50);
  if (std::sqrt(ss / static_cast<double>(all.size())) > o.max_rms_px || far > limit || std::min(plus, minus) > limit)
    return false;
  order_along(all, pl);
  a.pts = std::move(all);
  a.plane = pl;
  a.great = fit_plane(a.pts, idx, true);
  a.length = arc_length(a.pts, 0, a.pts.size());
  return true;
}

double bilinear(const cv::Mat& m, double x, double y) {
  x = std::clamp(x, 0.0, m.cols - 1.001);
  y = std::clamp(y, 0.0, m.rows - 1.001);
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const double fx = x - x0, fy = y - y0;
  const float* r0 = m.ptr<float>(y0);
  const float* r1 = m.ptr<float>(y0 + 1);
  return (1 - fy) * ((1 - fx) * r0[x0] + fx * r0[x0 + 1]) + fy * ((1 - fx) * r1[x0] + fx * r1[x0 + 1]);
}

// Edge pixels chained end to end: from every end pixel (one neighbour) first, then from what is left (loops),
// each chain grown both ways, always to the unvisited neighbour straightest ahead.
std::vector<std::vector<cv::Point>> chain_edges(const cv::Mat& edges) {
  static const int kDx[8] = {1, 0, -1, 0, 1, -1, -1, 1}, kDy[8] = {0, 1, 0, -1, 1, 1, -1, -1};
  cv::Mat visited = cv::Mat::zeros(edges.size(), CV_8U);
  const auto is_edge = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < edges.cols && y < edges.rows && edges.at<std::uint8_t>(y, x) != 0;
  };
  const auto free_edge = [&](int x, int y) { return is_edge(x, y) && visited.at<std::uint8_t>(y, x) == 0; };
  std::vector<cv::Point> ends, others;
  for (int y = 0; y < edges.rows; ++y)
    for (int x = 0; x < edges.cols; ++x) {
      if (!is_edge(x, y)) continue;
      int count = 0;
      for (int k = 0; k < 8; ++k) count += is_edge(x + kDx[k], y + kDy[k]);
      (count == 1 ? ends : others).emplace_back(x, y);
    }
  const auto grow = [&](std::vector<cv::Point>& chain) {
    for (;;) {
      const cv::Point cur = chain.back();
      cv::Point2d dir(0, 0);
      if (chain.size() >= 2) {
        const cv::Point back = chain[chain.size() - std::min<std::size_t>(chain.size(), 6)];
        dir = cv::Point2d(cur - back);
        const double len = cv::norm(dir);
        if (len > 0) dir *= 1 / len;
      }
      int best = -1;
      double best_score = -1e9;
      for (int k = 0; k < 8; ++k) {
        const int x = cur.x + kDx[k], y = cur.y + kDy[k];
        if (!free_edge(x, y)) continue;
        const cv::Point2d step(kDx[k], kDy[k]);
        // Straight ahead first; among equals the 4-neighbour (a diagonal step skips a corner pixel).
        const double score = step.dot(dir) / cv::norm(step) + (k < 4 ? 1e-3 : 0);
        if (score > best_score) best_score = score, best = k;
      }
      if (best < 0) return;
      const cv::Point next(cur.x + kDx[best], cur.y + kDy[best]);
      visited.at<std::uint8_t>(next) = 1;
      chain.push_back(next);
    }
  };
  std::vector<std::vector<cv::Point>> chains;
  for (const auto* list : {&ends, &others})
    for (const cv::Point& s : *list) {
      if (visited.at<std::uint8_t>(s)) continue;
      visited.at<std::uint8_t>(s) = 1;
      std::vector<cv::Point> fwd{s};
      grow(fwd);
      std::vector<cv::Point> bwd{s};
      grow(bwd);
      std::reverse(bwd.begin(), bwd.end());
      bwd.insert(bwd.end(), fwd.begin() + 1, fwd.end());
      chains.push_back(std::move(bwd));
    }
  return chains;
}

// Splits a chain (sub-pixel points) where it turns by more than `corner_deg` over +-w points.
std::vector<std::vector<cv::Point2d>> split_corners(const std::vector<cv::Point2d>& c, double corner_deg) {
  constexpr int w = 5;
  std::vector<std::vector<cv::Point2d>> out;
  const int n = static_cast<int>(c.size());
  if (n < 2 * w + 1) {
    out.push_back(c);
    return out;
  }
  const double limit = std::cos(corner_deg * CV_PI / 180);
  std::vector<double> turn(static_cast<std::size_t>(n), 1.0);  // cosine of the turn
  for (int i = w; i < n - w; ++i) {
    const cv::Point2d a = c[static_cast<std::size_t>(i)] - c[static_cast<std::size_t>(i - w)];
    const cv::Point2d b = c[static_cast<std::size_t>(i + w)] - c[static_cast<std::size_t>(i)];
    const double la = cv::norm(a), lb = cv::norm(b);
    if (la > 0 && lb > 0) turn[static_cast<std::size_t>(i)] = a.dot(b) / (la * lb);
  }
  int start = 0;
  for (int i = w; i < n - w; ++i) {
    if (turn[static_cast<std::size_t>(i)] >= limit) continue;
    // The sharpest point of this corner: run to the end of the stretch above the limit.
    int j = i, sharpest = i;
    while (j < n - w && turn[static_cast<std::size_t>(j)] < limit) {
      if (turn[static_cast<std::size_t>(j)] < turn[static_cast<std::size_t>(sharpest)]) sharpest = j;
      ++j;
    }
    const int cut_lo = std::max(start, sharpest - w / 2), cut_hi = std::min(n, sharpest + w / 2 + 1);
    if (cut_lo > start) out.emplace_back(c.begin() + start, c.begin() + cut_lo);
    start = cut_hi;
    i = j;
  }
  if (start < n) out.emplace_back(c.begin() + start, c.end());
  return out;
}

// Returned points: every `spacing` px of arc length, each the mean of the kept edge points within +-3 indices that
// are no more than 4 px from it (no averaging across gaps).
PickedLine sample_points(const std::vector<RayPoint>& pts, double spacing) {
  PickedLine out;
  double since = spacing;  // the first point is taken
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (i > 0) since += cv::norm(pts[i].px - pts[i - 1].px);
    const bool last = i + 1 == pts.size();
    if (since < spacing && !last) continue;
    if (last && since < spacing / 2 && !out.empty()) out.pop_back();
    since = 0;
    cv::Point2d sum(0, 0);
    int count = 0;
    for (std::size_t j = i >= 3 ? i - 3 : 0; j < std::min(pts.size(), i + 4); ++j)
      if (cv::norm(pts[j].px - pts[i].px) <= 4) sum += pts[j].px, ++count;
    out.push_back(sum * (1.0 / count));
  }
  return out;
}

std::vector<RayPoint> to_ray_points(const Lens& lens, const PickedLine& points, std::vector<std::size_t>* source) {
  std::vector<RayPoint> pts;
  for (std::size_t i = 0; i < points.size(); ++i) {
    RayPoint r;
    if (!ray_point(lens, points[i], r)) continue;
    pts.push_back(r);
    if (source) source->push_back(i);
  }
  return pts;
}

double polyline_distance(const PickedLine& line, const cv::Point2d& q) {
  double best = 1e300;
  for (std::size_t i = 0; i < line.size(); ++i) {
    best = std::min(best, cv::norm(line[i] - q));
    if (i + 1 == line.size()) break;
    const cv::Point2d a = line[i], d = line[i + 1] - line[i];
    const double l2 = d.dot(d);
    if (l2 <= 0) continue;
    const double t = std::clamp((q - a).dot(d) / l2, 0.0, 1.0);
    best = std::min(best, cv::norm(a + t * d - q));
  }
  return best;
}

double rss(const std::vector<RayPoint>& pts, std::size_t lo, std::size_t hi) {
  std::vector<std::size_t> idx(hi - lo);
  std::iota(idx.begin(), idx.end(), lo);
  Plane pl = fit_plane(pts, idx, false);
  pl = fit_plane(pts, idx, false, &pl);
  double s = 0;
  for (const auto i : idx) s += px_distance(pl, pts[i]) * px_distance(pl, pts[i]);
  return s;
}

// How much better the line fits as two curves (split where that helps most, between 15 % and 85 % of its points)
// than as one: sqrt((RSS one - RSS two) / n), px. A line of the world, even through a wrong lens, bends smoothly
// and one curve fits it about as well; two lines meeting at a slight angle (a stripe running on from a wall onto
// the ceiling, in one plane that misses the camera) fit two far better.
double kink(const std::vector<RayPoint>& pts, double rss_one) {
  const std::size_t n = pts.size();
  if (n < 40) return 0;
  double best = rss_one;
  for (int k = 3; k <= 17; ++k) {
    const std::size_t at = n * static_cast<std::size_t>(k) / 20;
    best = std::min(best, rss(pts, 0, at) + rss(pts, at, n));
  }
  return std::sqrt(std::max(0.0, rss_one - best) / static_cast<double>(n));
}

}  // namespace

PickedLine drop_line_outliers(const Lens& lens, const PickedLine& points, double inlier_px, int* dropped) {
  if (dropped) *dropped = 0;
  if (points.size() < 3) return points;
  std::vector<std::size_t> source;
  const auto pts = to_ray_points(lens, points, &source);
  if (pts.size() < 3) return points;
  Plane pl;
  auto keep = robust_keep(pts, inlier_px, pl);
  std::sort(keep.begin(), keep.end());
  PickedLine out;
  for (const auto i : keep) out.push_back(points[source[i]]);
  if (dropped) *dropped = static_cast<int>(points.size() - out.size());
  return out;
}

LineProposals propose_lines(const cv::Mat& image, const Lens& lens, const LineProposalOptions& o) {
  if (image.empty()) throw std::invalid_argument("line proposals: empty image");
  if (image.channels() != 1 && image.channels() != 3)
    throw std::invalid_argument("line proposals: the image must have 1 or 3 channels");
  if (!(o.blur_sigma >= 0) || !(o.canny_low > 0) || !(o.canny_high >= o.canny_low) || !(o.inlier_px > 0) ||
      !(o.point_spacing_px > 0) || !(o.min_length_px >= 0) || !(o.max_bend_px >= 0) || !(o.max_rms_px > 0))
    throw std::invalid_argument("line proposals: bad options");
  lens.validate();
  LineProposals result;

  // 1. Gray in [0, 1] between the dark surround and the bright level.
  cv::Mat gray;
  {
    cv::Mat f;
    image.convertTo(f, CV_32F);
    if (f.channels() == 3)
      cv::cvtColor(f, gray, cv::COLOR_BGR2GRAY);
    else
      gray = f;
  }
  std::vector<float> sample;
  for (int y = 0; y < gray.rows; y += 4)
    for (int x = 0; x < gray.cols; x += 4) sample.push_back(gray.at<float>(y, x));
  std::sort(sample.begin(), sample.end());
  const double dark = sample[sample.size() / 100], bright = sample[sample.size() * 99 / 100];
  if (!(bright > dark)) return result;
  gray = (gray - dark) / (bright - dark);

  // The lit disc, shrunk by the margin: the convex hull of the largest lit region.
  cv::Mat mask;
  {
    cv::Mat smooth, lit;
    cv::GaussianBlur(gray, smooth, cv::Size(0, 0), 2.0);
    cv::threshold(smooth, lit, 0.08, 255, cv::THRESH_BINARY);
    lit.convertTo(lit, CV_8U);
    cv::Mat labels, stats, centroids;
    const int count = cv::connectedComponentsWithStats(lit, labels, stats, centroids, 8);
    int best = -1, best_area = 0;
    for (int i = 1; i < count; ++i)
      if (stats.at<int>(i, cv::CC_STAT_AREA) > best_area) best_area = stats.at<int>(i, cv::CC_STAT_AREA), best = i;
    if (best < 0) return result;
    std::vector<cv::Point> pts;
    for (int y = 0; y < labels.rows; ++y)
      for (int x = 0; x < labels.cols; ++x)
        if (labels.at<int>(y, x) == best) pts.emplace_back(x, y);
    std::vector<cv::Point> hull;
    cv::convexHull(pts, hull);
    cv::Mat disc = cv::Mat::zeros(gray.size(), CV_8U);
    cv::fillConvexPoly(disc, hull, cv::Scalar(255));
    cv::Mat dist;
    cv::distanceTransform(disc, dist, cv::DIST_L2, 5);
    mask = dist > o.rim_margin_px;
  }

  // 2. Gradient, Canny, sub-pixel edge points.
  cv::Mat blurred, dx, dy, mag;
  if (o.blur_sigma > 0)
    cv::GaussianBlur(gray, blurred, cv::Size(0, 0), o.blur_sigma);
  else
    blurred = gray;
  cv::Sobel(blurred, dx, CV_32F, 1, 0, 3, 1.0 / 8);
  cv::Sobel(blurred, dy, CV_32F, 0, 1, 3, 1.0 / 8);
  cv::magnitude(dx, dy, mag);
  constexpr double kScale = 4000;  // gradient per px -> Canny's 16-bit derivatives
  cv::Mat dx16, dy16, edges;
  dx.convertTo(dx16, CV_16S, kScale);
  dy.convertTo(dy16, CV_16S, kScale);
  cv::Canny(dx16, dy16, edges, o.canny_low * kScale, o.canny_high * kScale, true);
  edges &= mask;
  result.edge_pixels = cv::countNonZero(edges);
  const auto subpixel = [&](const cv::Point& p) {
    const double gx = dx.at<float>(p), gy = dy.at<float>(p), m0 = mag.at<float>(p);
    const double g = std::hypot(gx, gy);
    if (!(g > 0)) return cv::Point2d(p);
    const double ux = gx / g, uy = gy / g;
    const double mm = bilinear(mag, p.x - ux, p.y - uy), mp = bilinear(mag, p.x + ux, p.y + uy);
    const double denom = mm - 2 * m0 + mp;
    double t = denom < 0 ? 0.5 * (mm - mp) / denom : 0;
    t = std::clamp(t, -0.5, 0.5);
    return cv::Point2d(p.x + t * ux, p.y + t * uy);
  };

  // 3. Chains, split at corners, as rays.
  const auto chains = chain_edges(edges);
  result.chains = static_cast<int>(chains.size());
  cv::RNG rng(0x5eed);
  std::vector<Piece> pieces;
  for (const auto& chain : chains) {
    if (chain.size() < 8) continue;
    std::vector<cv::Point2d> sub;
    sub.reserve(chain.size());
    for (const auto& p : chain) sub.push_back(subpixel(p));
    for (const auto& part : split_corners(sub, o.corner_deg)) {
      // Runs of points with a ray (a Kannala-Brandt lens may have none beyond where its polynomial turns).
      std::vector<RayPoint> run;
      const auto flush = [&] {
        if (run.size() >= 8) split_straight(run, 0, run.size(), o.inlier_px, rng, pieces);
        run.clear();
      };
      for (const auto& p : part) {
        const cv::Point ip(cvRound(p.x), cvRound(p.y));
        cv::Point2d g(dx.at<float>(ip), dy.at<float>(ip));
        if (const double len = cv::norm(g); len > 0) g *= 1 / len;
        RayPoint r;
        if (ray_point(lens, p, r, g))
          run.push_back(r);
        else
          flush();
      }
      flush();
    }
  }
  result.pieces = static_cast<int>(pieces.size());

  // 4. Merge pieces of one line, longest first.
  std::sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) { return a.length > b.length; });
  std::vector<char> dead(pieces.size(), 0);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (dead[i]) continue;
    for (bool grew = true; grew;) {
      grew = false;
      for (std::size_t j = i + 1; j < pieces.size(); ++j)
        if (!dead[j] && try_merge(pieces[i], pieces[j], o)) dead[j] = 1, grew = true;
    }
  }

  // 5. Second pass: robust refit, outliers dropped, then length, roughness and bend.
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (dead[i]) continue;
    const Piece& p = pieces[i];
    if (p.length < o.min_length_px) {
      ++result.rejected_short;
      continue;
    }
    Plane pl;
    auto keep = robust_keep(p.pts, o.inlier_px, pl);
    std::sort(keep.begin(), keep.end());
    std::vector<RayPoint> kept;
    for (const auto k : keep) kept.push_back(p.pts[k]);
    ProposedLine line;
    line.edge_pixels = static_cast<int>(kept.size());
    line.outliers = static_cast<int>(p.pts.size() - kept.size());
    line.length_px = arc_length(kept, 0, kept.size());
    double ss = 0;
    for (const auto& r : kept) ss += px_distance(pl, r) * px_distance(pl, r);
    line.rms_px = std::sqrt(ss / std::max<double>(1, static_cast<double>(kept.size())));
    Plane great = fit_plane(kept, all_of(kept), true);
    great = fit_plane(kept, all_of(kept), true, &great);
    for (const auto& r : kept) line.bend_px = std::max(line.bend_px, std::abs(px_distance(great, r)));
    line.kink_px = kink(kept, ss);
    if (line.length_px < o.min_length_px || line.rms_px > o.max_rms_px || kept.size() < 8) {
      ++result.rejected_short;
      continue;
    }
    if (line.bend_px > o.max_bend_px) {
      ++result.rejected_bent;
      continue;
    }
    line.points = sample_points(kept, o.point_spacing_px);
    if (line.points.size() < 3) {
      ++result.rejected_short;
      continue;
    }
    result.lines.push_back(std::move(line));
  }
  std::sort(result.lines.begin(), result.lines.end(),
            [](const ProposedLine& a, const ProposedLine& b) { return a.length_px > b.length_px; });
  if (o.max_lines > 0 && result.lines.size() > static_cast<std::size_t>(o.max_lines))
    result.lines.resize(static_cast<std::size_t>(o.max_lines));
  return result;
}

std::vector<PickedLine> proposal_points(const LineProposals& proposals) {
  std::vector<PickedLine> out;
  out.reserve(proposals.lines.size());
  for (const auto& l : proposals.lines) out.push_back(l.points);
  return out;
}

std::vector<PickedLine> lines_not_in(const std::vector<PickedLine>& proposals, const std::vector<PickedLine>& existing,
                                     double tol_px) {
  std::vector<PickedLine> out;
  for (const auto& p : proposals) {
    bool repeat = false;
    for (const auto& e : existing) {
      if (e.size() < 2 || p.empty()) continue;
      std::size_t near = 0;
      for (const auto& q : p) near += polyline_distance(e, q) <= tol_px;
      if (2 * near > p.size()) {
        repeat = true;
        break;
      }
    }
    if (!repeat) out.push_back(p);
  }
  return out;
}

}  // namespace bs::vision
