// SPDX-License-Identifier: GPL-3.0-or-later
#include "vision/reproject/fast_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include <opencv2/core/utility.hpp>

namespace bs::vision {
namespace {

constexpr double kPi = 3.14159265358979323846;

enum class NodeKind : unsigned char { Smooth, Far, Exact };

struct Node {
  float x = -1, y = -1;
  NodeKind kind = NodeKind::Far;
};

enum class CellKind : unsigned char { Interpolate, Fine, Empty, Exact };

}  // namespace

void build_reprojection_map_coarse(const Lens& lens, const View& view, cv::Mat& map, int step) {
  lens.validate();
  view.validate();
  if (step < 1 || step > 256) throw std::invalid_argument("coarse map step must be in [1, 256] pixels");
  // Bilinear error grows with the square of a cell's angular size and with the source pixels per radian (1/r_pp):
  // measured ~0.12 px * (cell angle)^2 / r_pp. Cells of at most sqrt(0.5 r_pp) radians keep it near 0.06 px, e.g.
  // 8 px cells for the paper's lens and 150 degree view; narrow focal lengths get smaller cells, down to exact.
  const double f = view.focal_px();
  step = std::clamp(static_cast<int>(std::floor(std::sqrt(0.5 * lens.r_pp) * f)), 1, step);
  if (step > 2 && step % 2) --step;  // even, so half cells fall on whole pixels
  if (step == 1) {
    map = build_reprojection_map(lens, view);
    return;
  }
  const int W = view.width, H = view.height;
  // Nodes at multiples of step up to the first one past the last pixel, so every pixel has a cell.
  const int nx = (W - 1) / step + 2, ny = (H - 1) / step + 2;
  const cv::Matx33d R = view_rotation(view);
  const cv::Point2d c = lens.centre();
  const double theta_max = std::min(lens.fov_deg * kPi / 360.0, lens.type == LensType::Orthographic ? kPi / 2 : kPi);
  const auto rmax_opt = lens.radius(theta_max);
  const double rmax = rmax_opt ? *rmax_opt : 0.0;
  const double rmax2 = rmax * rmax * (1 + 1e-9);
  const double margin = std::max(15.0 * kPi / 180.0, 3.0 * step / f);
  Lens unclipped = lens;  // the model continued past its field of view (radius() checks fov_deg first)
  unclipped.fov_deg = 360;
  const double ox = (W - 1) / 2.0, oy = (H - 1) / 2.0;

  // The lens maths on a grid of half cells: the even points are the interpolation nodes, the odd ones (cell
  // centres and edge midpoints) check each cell's bilinear error a posteriori.
  const int hx = 2 * nx - 1, hy = 2 * ny - 1;
  const int half = step / 2;
  std::vector<Node> grid(static_cast<std::size_t>(hx) * hy);
  // OpenCV's pool, not OpenMP: remap runs on that pool right after, and an OpenMP team spinning after its loop
  // competes with it for the two cores (bench tuner: 48 ms against 6 ms for the build under load).
  cv::parallel_for_(cv::Range(0, hy), [&](const cv::Range& range) {
    for (int j = range.start; j < range.end; ++j)
      for (int i = 0; i < hx; ++i) {
        cv::Vec3d v(f, i * half - ox, oy - j * half);
        v = R * (v / cv::norm(v));
        const double theta = std::acos(std::clamp(v[0], -1.0, 1.0));
        Node& n = grid[static_cast<std::size_t>(j) * hx + i];
        if (theta > theta_max + margin) continue;  // Far
        const auto r = unclipped.radius(theta);
        if (!r || theta > kPi - 0.2) {
          n.kind = NodeKind::Exact;
          continue;
        }
        const double len = std::hypot(v[1], v[2]);
        n.x = static_cast<float>(c.x + (len > 0 ? *r * v[1] / len : 0.0));
        n.y = static_cast<float>(c.y - (len > 0 ? *r * v[2] / len : 0.0));
        n.kind = NodeKind::Smooth;
      }
  });
  const auto at = [&](int i, int j) -> const Node& { return grid[static_cast<std::size_t>(j) * hx + i]; };
  const float max_x = static_cast<float>(lens.width - 1), max_y = static_cast<float>(lens.height - 1);
  const float ccx = static_cast<float>(c.x), ccy = static_cast<float>(c.y);
  const auto valid = [&](float px, float py) {
    const double rx = px - ccx, ry = py - ccy;
    return rx * rx + ry * ry <= rmax2 && px >= 0 && py >= 0 && px <= max_x && py <= max_y;
  };
  std::vector<Node> nodes(static_cast<std::size_t>(nx) * ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) nodes[static_cast<std::size_t>(j) * nx + i] = at(2 * i, 2 * j);

  const int cx_cells = nx - 1, cy_cells = ny - 1;
  std::vector<CellKind> cells(static_cast<std::size_t>(cx_cells) * cy_cells);
  // A bilinear value is a convex combination of its four corners, and the valid area (disc within the image
  // rectangle) is convex: when all nine points of a cell are valid, no pixel of it needs the per-pixel test.
  std::vector<char> inside(cells.size(), 0);
  constexpr float kTolerance = 0.04f;  // px, at the checked points; the maximum in between stays under 0.1 px
  cv::parallel_for_(cv::Range(0, cy_cells), [&](const cv::Range& range) {
    for (int j = range.start; j < range.end; ++j)
      for (int i = 0; i < cx_cells; ++i) {
        int smooth = 0, far = 0;
        for (int dj = 0; dj < 3; ++dj)
          for (int di = 0; di < 3; ++di) {
            const NodeKind k = at(2 * i + di, 2 * j + dj).kind;
            smooth += k == NodeKind::Smooth;
            far += k == NodeKind::Far;
          }
        CellKind kind = smooth == 9 ? CellKind::Interpolate : far == 9 ? CellKind::Empty : CellKind::Exact;
        if (kind == CellKind::Interpolate) {
          const Node &a = at(2 * i, 2 * j), &b = at(2 * i + 2, 2 * j), &cc = at(2 * i, 2 * j + 2),
                     &d = at(2 * i + 2, 2 * j + 2);
          const auto off = [](const Node& exact, float x, float y) { return std::hypot(exact.x - x, exact.y - y); };
          const float err =
              std::max({off(at(2 * i + 1, 2 * j + 1), (a.x + b.x + cc.x + d.x) / 4, (a.y + b.y + cc.y + d.y) / 4),
                        off(at(2 * i + 1, 2 * j), (a.x + b.x) / 2, (a.y + b.y) / 2),
                        off(at(2 * i + 1, 2 * j + 2), (cc.x + d.x) / 2, (cc.y + d.y) / 2),
                        off(at(2 * i, 2 * j + 1), (a.x + cc.x) / 2, (a.y + cc.y) / 2),
                        off(at(2 * i + 2, 2 * j + 1), (b.x + d.x) / 2, (b.y + d.y) / 2)});
          // Halving the spacing quarters the bilinear error: interpolate on the half-cell grid when that is enough.
          if (err > 4 * kTolerance)
            kind = CellKind::Exact;
          else if (err > kTolerance)
            kind = CellKind::Fine;
        }
        cells[static_cast<std::size_t>(j) * cx_cells + i] = kind;
        if (kind == CellKind::Interpolate || kind == CellKind::Fine) {
          bool all = true;
          for (int dj = 0; dj < 3 && all; ++dj)
            for (int di = 0; di < 3 && all; ++di)
              all = valid(at(2 * i + di, 2 * j + dj).x, at(2 * i + di, 2 * j + dj).y);
          inside[static_cast<std::size_t>(j) * cx_cells + i] = all;
        }
      }
  });

  map.create(H, W, CV_32FC2);  // reused when the size is unchanged: fresh pages cost more than the maths here
  const float inv_step = 1.0f / static_cast<float>(step);
  // One row span of a cell: linear in x from (ax, ay) with slope (dx, dy) per pixel.
  const auto fill_span = [&valid](cv::Vec2f* row, int from, int to, float ax, float ay, float dx, float dy,
                                  bool all_inside) {
    float* out = &row[from][0];
    const int n = to - from;
    if (all_inside) {
      for (int k = 0; k < n; ++k) {
        out[2 * k] = ax + dx * static_cast<float>(k);
        out[2 * k + 1] = ay + dy * static_cast<float>(k);
      }
      return;
    }
    for (int k = 0; k < n; ++k) {
      const float px = ax + dx * static_cast<float>(k), py = ay + dy * static_cast<float>(k);
      const bool ok = valid(px, py);
      out[2 * k] = ok ? px : -1.0f;
      out[2 * k + 1] = ok ? py : -1.0f;
    }
  };
  cv::parallel_for_(cv::Range(0, H), [&](const cv::Range& range) {
    for (int y = range.start; y < range.end; ++y) {
      auto* row = map.ptr<cv::Vec2f>(y);
      const int j = y / step;
      const float t = static_cast<float>(y - j * step) * inv_step;
      const Node* top = &nodes[static_cast<std::size_t>(j) * nx];
      const Node* bottom = top + nx;
      for (int i = 0; i < cx_cells; ++i) {
        const int x0 = i * step, x1 = std::min(x0 + step, W);
        const CellKind kind = cells[static_cast<std::size_t>(j) * cx_cells + i];
        const bool all_inside = inside[static_cast<std::size_t>(j) * cx_cells + i];
        if (kind == CellKind::Empty) {
          for (int x = x0; x < x1; ++x) row[x] = cv::Vec2f(-1, -1);
        } else if (kind == CellKind::Exact) {
          for (int x = x0; x < x1; ++x) {
            const auto s = source_of(lens, view, x, y);
            row[x] = s ? cv::Vec2f(static_cast<float>(s->x), static_cast<float>(s->y)) : cv::Vec2f(-1, -1);
          }
        } else if (kind == CellKind::Fine) {
          // Bilinear on the half-cell grid: rows 2j..2j+2, columns 2i..2i+2 of `grid`.
          const int yy = y - j * step, sj = 2 * j + (yy >= half ? 1 : 0);
          const float ft = static_cast<float>(yy - (yy >= half ? half : 0)) / static_cast<float>(half);
          for (int sub = 0; sub < 2; ++sub) {
            const int si = 2 * i + sub, sx0 = x0 + sub * half, sx1 = std::min(sx0 + half, x1);
            const Node &p00 = at(si, sj), &p10 = at(si + 1, sj), &p01 = at(si, sj + 1), &p11 = at(si + 1, sj + 1);
            const float ax = p00.x + (p01.x - p00.x) * ft, ay = p00.y + (p01.y - p00.y) * ft;
            const float bx = p10.x + (p11.x - p10.x) * ft, by = p10.y + (p11.y - p10.y) * ft;
            const float inv_half = 1.0f / static_cast<float>(half);
            const float dx = (bx - ax) * inv_half, dy = (by - ay) * inv_half;
            fill_span(row, sx0, sx1, ax, ay, dx, dy, all_inside);
          }
        } else {
          // Vertical interpolation at the cell's two node columns, then horizontal along the row.
          const float ax = top[i].x + (bottom[i].x - top[i].x) * t, ay = top[i].y + (bottom[i].y - top[i].y) * t;
          const float bx = top[i + 1].x + (bottom[i + 1].x - top[i + 1].x) * t;
          const float by = top[i + 1].y + (bottom[i + 1].y - top[i + 1].y) * t;
          const float dx = (bx - ax) * inv_step, dy = (by - ay) * inv_step;
          fill_span(row, x0, x1, ax, ay, dx, dy, all_inside);
        }
      }
    }
  });
}

cv::Mat build_reprojection_map_coarse(const Lens& lens, const View& view, int step) {
  cv::Mat map;
  build_reprojection_map_coarse(lens, view, map, step);
  return map;
}

}  // namespace bs::vision
