#pragma once
// A small drawing surface over cairo for gesmi's pictures: a PNG canvas with a
// data-to-pixel mapping, axes with ticks in data units, and text. Written to a
// temporary name and renamed (AtomicOutput).

#include <memory>
#include <string>

struct _cairo;
struct _cairo_surface;

namespace gesmi::io {

struct Rgb {
  double r, g, b;
};

/// A rectangle of data space [x0, x1] x [y0, y1] drawn into a pixel frame.
struct DataFrame {
  double x0, x1, y0, y1;       // data bounds
  double left, top, width, height;  // pixel frame
  bool y_down = false;         // true: y grows downwards (time axes)
  double px(double x) const { return left + (x - x0) / (x1 - x0) * width; }
  double py(double y) const {
    const double f = (y - y0) / (y1 - y0);
    return y_down ? top + f * height : top + (1.0 - f) * height;
  }
};

class Canvas {
 public:
  Canvas(int width, int height);
  ~Canvas();
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;

  _cairo* cr() { return cr_; }
  /// Fills the whole pixels the rectangle touches (its edges rounded outward), without
  /// anti-aliasing: a filled box is never drawn smaller than it is, and axis-aligned
  /// fills cost no coverage computation.
  void fill_rect(double x, double y, double w, double h, Rgb colour, double alpha = 1.0);
  void stroke_rect(double x, double y, double w, double h, Rgb colour, double line_width);
  void line(double x0, double y0, double x1, double y1, Rgb colour, double line_width);
  void dot(double x, double y, double radius, Rgb colour);
  void text(double x, double y, const std::string& s, double size, Rgb colour, bool centred = false);
  /// Frame, ticks and labels for a data frame.
  void axes(const DataFrame& f, const std::string& x_label, const std::string& y_label);
  /// Writes the PNG atomically, with libpng's fast settings (cairo's writer uses zlib's
  /// default level and adaptive filters, several times slower for a few % of size);
  /// throws FormatError on failure.
  void save_png(const std::string& path);

 private:
  _cairo_surface* surface_;
  _cairo* cr_;
};

/// A "nice" tick step (1, 2 or 5 times a power of ten) for a span and tick count.
double tick_step(double span, int target_ticks);

}  // namespace gesmi::io
