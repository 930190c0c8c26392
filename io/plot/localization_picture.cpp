#include "io/plot/localization_picture.h"

#include <algorithm>
#include <cmath>

#include <cairo.h>

#include "io/plot/canvas.h"
#include "solver/model/angles.h"

namespace gesmi::io {
namespace {

const Rgb kBlack{0, 0, 0}, kGrey{0.5, 0.5, 0.5}, kInner{0.85, 0.1, 0.1}, kBoundary{0.95, 0.8, 0.1},
    kLandmark{0.1, 0.3, 0.9}, kTruth{0.0, 0.6, 0.2}, kHull{0.3, 0.3, 0.3};

struct Range2 {
  double x0 = kInf, x1 = -kInf, y0 = kInf, y1 = -kInf;
  void add(double x, double y) {
    x0 = std::min(x0, x);
    x1 = std::max(x1, x);
    y0 = std::min(y0, y);
    y1 = std::max(y1, y);
  }
  bool empty() const { return !(x0 <= x1); }
  // Grows by a fraction of its size (at least `floor`) on each side.
  Range2 padded(double fraction, double floor) const {
    const double dx = std::max((x1 - x0) * fraction, floor), dy = std::max((y1 - y0) * fraction, floor);
    return {x0 - dx, x1 + dx, y0 - dy, y1 + dy};
  }
};

// Equal scales on both axes inside the pixel frame (for the (x, y) panels).
DataFrame equal_aspect(Range2 r, double left, double top, double width, double height) {
  const double sx = (r.x1 - r.x0) / width, sy = (r.y1 - r.y0) / height, s = std::max(sx, sy);
  const double cx = 0.5 * (r.x0 + r.x1), cy = 0.5 * (r.y0 + r.y1);
  return {cx - s * width / 2, cx + s * width / 2, cy - s * height / 2, cy + s * height / 2, left, top, width, height};
}

// Clips a data rectangle to the frame and fills it, at least one pixel wide.
void draw_box(Canvas& c, const DataFrame& f, double x0, double x1, double y0, double y1, Rgb colour) {
  x0 = std::max(x0, f.x0);
  x1 = std::min(x1, f.x1);
  y0 = std::max(y0, f.y0);
  y1 = std::min(y1, f.y1);
  if (x0 > x1 || y0 > y1) return;
  const double px = f.px(x0), py = f.py(y1);
  c.fill_rect(px, py, std::max(1.0, f.px(x1) - px), std::max(1.0, f.py(y0) - py), colour, 0.9);
}

// Restricts drawing to a panel's frame while alive.
class Clip {
 public:
  Clip(Canvas& c, const DataFrame& f) : cr_(c.cr()) {
    cairo_save(cr_);
    cairo_rectangle(cr_, f.left, f.top, f.width, f.height);
    cairo_clip(cr_);
  }
  ~Clip() { cairo_restore(cr_); }
  Clip(const Clip&) = delete;
  Clip& operator=(const Clip&) = delete;

 private:
  _cairo* cr_;
};

void draw_map(Canvas& c, const DataFrame& f, const LocalizationProblem& p, double tick) {
  const Clip clip(c, f);
  for (const Segment& w : p.map.walls) {
    c.line(f.px(w.ax), f.py(w.ay), f.px(w.bx), f.py(w.by), kBlack, 2.0);
    // A short tick on the reflecting (left) side.
    const double len = std::hypot(w.bx - w.ax, w.by - w.ay), mx = 0.5 * (w.ax + w.bx), my = 0.5 * (w.ay + w.by);
    const double nx = -(w.by - w.ay) / len, ny = (w.bx - w.ax) / len;
    c.line(f.px(mx), f.py(my), f.px(mx + tick * nx), f.py(my + tick * ny), kGrey, 1.0);
  }
  for (const LandmarkPoint& l : p.map.landmarks) c.dot(f.px(l.x), f.py(l.y), 3.0, kLandmark);
}

// Projects the pavings on dimensions (a, b), scaled by the units.
void draw_pavings(Canvas& c, const DataFrame& f, const LocalizationResult& r, std::size_t a, std::size_t b, double unit_b) {
  const auto draw = [&](const Paving& paving, Rgb colour) {
    // Angles are drawn one turn either side too, so that wrapped hulls show all boxes.
    const double turn = b == 2 ? kTwoPi * unit_b : 0.0;
    for (std::size_t i = 0; i < paving.size(); ++i) {
      const auto box = paving.box(i);
      for (double shift : {-turn, 0.0, turn}) {
        draw_box(c, f, box[a].lo(), box[a].hi(), box[b].lo() * unit_b + shift, box[b].hi() * unit_b + shift, colour);
        if (turn == 0.0) break;
      }
    }
  };
  draw(r.paving.boundary, kBoundary);
  draw(r.paving.inner, kInner);
}

void draw_hulls(Canvas& c, const DataFrame& f, const LocalizationResult& r, std::size_t b, double unit_b) {
  const Clip clip(c, f);
  for (std::size_t k = 0; k < r.hypotheses.size() && k < 20; ++k) {
    const Box& h = r.hypotheses[k].component.hull;
    const double x0 = f.px(h[0].lo()), x1 = f.px(h[0].hi()), y0 = f.py(h[b].lo() * unit_b), y1 = f.py(h[b].hi() * unit_b);
    c.stroke_rect(std::min(x0, x1) - 2, std::min(y0, y1) - 2, std::abs(x1 - x0) + 4, std::abs(y1 - y0) + 4, kHull, 0.8);
    c.text(std::max(x0, x1) + 4, std::min(y0, y1) + 10, "#" + std::to_string(k + 1), 11, kHull);
  }
}

void draw_truth_xy(Canvas& c, const DataFrame& f, const LocalizationProblem& p, double arrow) {
  if (!p.truth) return;
  const Clip clip(c, f);
  const Pose<double>& t = *p.truth;
  c.dot(f.px(t.x), f.py(t.y), 4.0, kTruth);
  c.line(f.px(t.x), f.py(t.y), f.px(t.x + arrow * std::cos(t.theta)), f.py(t.y + arrow * std::sin(t.theta)), kTruth, 2.0);
}

void draw_truth_xtheta(Canvas& c, const DataFrame& f, const LocalizationProblem& p) {
  if (!p.truth) return;
  double th = p.truth->theta * kDegreesPerRadian;
  while (th > f.y1) th -= 360.0;
  while (th < f.y0) th += 360.0;
  c.dot(f.px(p.truth->x), f.py(th), 4.0, kTruth);
}

Range2 hypotheses_xy(const LocalizationResult& r) {
  Range2 z;
  for (const LocalizationHypothesis& h : r.hypotheses) {
    z.add(h.component.hull[0].lo(), h.component.hull[1].lo());
    z.add(h.component.hull[0].hi(), h.component.hull[1].hi());
  }
  return z;
}

}  // namespace

void write_localization_picture(const std::string& png_path, const LocalizationProblem& p, const LocalizationResult& r) {
  const int width = 1400, height = 1040;
  Canvas c(width, height);
  Range2 world;
  for (const Segment& w : p.map.walls) {
    world.add(w.ax, w.ay);
    world.add(w.bx, w.by);
  }
  for (const LandmarkPoint& l : p.map.landmarks) world.add(l.x, l.y);
  if (p.truth) world.add(p.truth->x, p.truth->y);
  if (world.empty()) world = {p.priors[0][0].lo(), p.priors[0][0].hi(), p.priors[0][1].lo(), p.priors[0][1].hi()};
  world = world.padded(0.05, 0.5);
  const double theta0 = p.priors[0][2].lo() * kDegreesPerRadian, theta1 = p.priors[0][2].hi() * kDegreesPerRadian;
  const double panel_w = 600, panel_h = 420;
  c.text(20, 24, "gesmi localize: " + (p.name.empty() ? std::string("scenario") : p.name) +
                     "   (red: inner boxes, yellow: boundary boxes, green: true pose, #k: hypotheses)", 15, kBlack);

  const DataFrame xy = equal_aspect(world, 70, 50, panel_w, panel_h);
  draw_pavings(c, xy, r, 0, 1, 1.0);
  draw_map(c, xy, p, 0.02 * (world.x1 - world.x0));
  draw_truth_xy(c, xy, p, 0.04 * (world.x1 - world.x0));
  c.axes(xy, "x (m)", "y (m)");

  const DataFrame xt{xy.x0, xy.x1, theta0, theta1, 770, 50, panel_w, panel_h};
  draw_pavings(c, xt, r, 0, 2, kDegreesPerRadian);
  draw_truth_xtheta(c, xt, p);
  c.axes(xt, "x (m)", "theta (deg)");

  const Range2 zoom_xy = hypotheses_xy(r);
  if (zoom_xy.empty()) {
    c.text(300, 760, "no pose is consistent with the data", 18, kBlack);
  } else {
    const Range2 z = zoom_xy.padded(0.15, 0.02);
    const DataFrame zxy = equal_aspect(z, 70, 560, panel_w, panel_h);
    draw_pavings(c, zxy, r, 0, 1, 1.0);
    draw_map(c, zxy, p, 0.02 * (zxy.x1 - zxy.x0));
    draw_hulls(c, zxy, r, 1, 1.0);
    draw_truth_xy(c, zxy, p, 0.04 * (zxy.x1 - zxy.x0));
    c.axes(zxy, "x (m), zoom on the hypotheses", "y (m)");
    double t0 = kInf, t1 = -kInf;
    for (const LocalizationHypothesis& h : r.hypotheses) {
      t0 = std::min(t0, h.component.hull[2].lo() * kDegreesPerRadian);
      t1 = std::max(t1, h.component.hull[2].hi() * kDegreesPerRadian);
    }
    const double pad = std::max(0.15 * (t1 - t0), 0.5);
    const DataFrame zxt{zxy.x0, zxy.x1, t0 - pad, t1 + pad, 770, 560, panel_w, panel_h};
    draw_pavings(c, zxt, r, 0, 2, kDegreesPerRadian);
    draw_hulls(c, zxt, r, 2, kDegreesPerRadian);
    draw_truth_xtheta(c, zxt, p);
    c.axes(zxt, "x (m), zoom", "theta (deg)");
  }
  c.save_png(png_path);
}

}  // namespace gesmi::io
