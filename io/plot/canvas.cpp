#include "io/plot/canvas.h"

#include <cairo.h>
#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <vector>

#include "io/output/atomic_output.h"
#include "io/format_error.h"

namespace gesmi::io {
namespace {

// Cairo's RGB24 pixels (32-bit words 0x00RRGGBB in native order) to an RGB PNG file,
// repacked a row at a time (a whole RGB copy of the waterfall picture was 4.7 MB of
// fresh memory), with libpng's fast settings for plots: no row filters, zlib level 1
// with run-length matching (flat fills compress to runs; 3-4 times faster than the
// simplified API's defaults here). libpng reports errors by longjmp to this frame: the
// row buffer is made before setjmp (a jump back skips no destructor), and neither it nor
// the two pointers are reassigned after setjmp.
// libpng's default handlers print to stderr: gesmi's one line says what failed instead.
[[noreturn]] void png_error_quietly(png_structp png, png_const_charp) { png_longjmp(png, 1); }
void png_warning_quietly(png_structp, png_const_charp) {}

bool write_rgb_png(std::FILE* file, const unsigned char* pixels, int width, int height, int stride) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, png_error_quietly, png_warning_quietly);
  if (!png) return false;
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    return false;
  }
  std::vector<unsigned char> rgb(static_cast<std::size_t>(width) * 3);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return false;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_set_compression_level(png, 1);
  png_set_compression_strategy(png, Z_RLE);
  png_write_info(png, info);
  for (int row = 0; row < height; ++row) {
    const unsigned char* words = pixels + static_cast<std::ptrdiff_t>(row) * stride;
    for (int col = 0; col < width; ++col) {
      std::uint32_t word;
      std::memcpy(&word, words + static_cast<std::ptrdiff_t>(col) * 4, sizeof word);
      unsigned char* o = &rgb[static_cast<std::size_t>(col) * 3];
      o[0] = static_cast<unsigned char>(word >> 16);
      o[1] = static_cast<unsigned char>(word >> 8);
      o[2] = static_cast<unsigned char>(word);
    }
    png_write_row(png, rgb.data());
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return true;
}

}  // namespace

Canvas::Canvas(int width, int height)
    : surface_(cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height)), cr_(cairo_create(surface_)) {
  cairo_set_source_rgb(cr_, 1, 1, 1);
  cairo_paint(cr_);
  cairo_select_font_face(cr_, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
}

Canvas::~Canvas() {
  cairo_destroy(cr_);
  cairo_surface_destroy(surface_);
}

void Canvas::fill_rect(double x, double y, double w, double h, Rgb c, double alpha) {
  const double x0 = std::floor(x), y0 = std::floor(y), x1 = std::ceil(x + w), y1 = std::ceil(y + h);
  cairo_set_source_rgba(cr_, c.r, c.g, c.b, alpha);
  cairo_set_antialias(cr_, CAIRO_ANTIALIAS_NONE);
  cairo_rectangle(cr_, x0, y0, std::max(x1 - x0, 1.0), std::max(y1 - y0, 1.0));
  cairo_fill(cr_);
  cairo_set_antialias(cr_, CAIRO_ANTIALIAS_DEFAULT);
}

void Canvas::stroke_rect(double x, double y, double w, double h, Rgb c, double line_width) {
  cairo_set_source_rgb(cr_, c.r, c.g, c.b);
  cairo_set_line_width(cr_, line_width);
  cairo_rectangle(cr_, x, y, w, h);
  cairo_stroke(cr_);
}

void Canvas::line(double x0, double y0, double x1, double y1, Rgb c, double line_width) {
  cairo_set_source_rgb(cr_, c.r, c.g, c.b);
  cairo_set_line_width(cr_, line_width);
  cairo_move_to(cr_, x0, y0);
  cairo_line_to(cr_, x1, y1);
  cairo_stroke(cr_);
}

void Canvas::dot(double x, double y, double radius, Rgb c) {
  cairo_set_source_rgb(cr_, c.r, c.g, c.b);
  cairo_arc(cr_, x, y, radius, 0, 2 * std::numbers::pi);
  cairo_fill(cr_);
}

void Canvas::text(double x, double y, const std::string& s, double size, Rgb c, bool centred) {
  cairo_set_source_rgb(cr_, c.r, c.g, c.b);
  cairo_set_font_size(cr_, size);
  if (centred) {
    cairo_text_extents_t e;
    cairo_text_extents(cr_, s.c_str(), &e);
    x -= e.width / 2 + e.x_bearing;
  }
  cairo_move_to(cr_, x, y);
  cairo_show_text(cr_, s.c_str());
}

double tick_step(double span, int target_ticks) {
  if (!(span > 0.0) || !std::isfinite(span)) return 1.0;
  const double raw = span / std::max(target_ticks, 1);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 5.0, 10.0})
    if (m * power >= raw) return m * power;
  return 10.0 * power;
}

void Canvas::axes(const DataFrame& f, const std::string& x_label, const std::string& y_label) {
  const Rgb black{0, 0, 0}, grey{0.55, 0.55, 0.55};
  stroke_rect(f.left, f.top, f.width, f.height, black, 1.0);
  char label[32];
  const double sx = tick_step(f.x1 - f.x0, 6);
  for (double x = std::ceil(f.x0 / sx) * sx; x <= f.x1 + 1e-9 * sx; x += sx) {
    line(f.px(x), f.top + f.height, f.px(x), f.top + f.height + 5, black, 1.0);
    std::snprintf(label, sizeof label, "%g", x);
    text(f.px(x), f.top + f.height + 18, label, 11, black, true);
  }
  const double sy = tick_step(f.y1 - f.y0, 8);
  for (double y = std::ceil(f.y0 / sy) * sy; y <= f.y1 + 1e-9 * sy; y += sy) {
    line(f.left - 5, f.py(y), f.left, f.py(y), black, 1.0);
    std::snprintf(label, sizeof label, "%g", y);
    cairo_text_extents_t e;
    cairo_set_font_size(cr_, 11);
    cairo_text_extents(cr_, label, &e);
    text(f.left - 8 - e.width, f.py(y) + 4, label, 11, black);
  }
  text(f.left + f.width / 2, f.top + f.height + 36, x_label, 12, grey, true);
  cairo_save(cr_);
  cairo_translate(cr_, f.left - 48, f.top + f.height / 2);
  cairo_rotate(cr_, -std::numbers::pi / 2);
  text(0, 0, y_label, 12, grey, true);
  cairo_restore(cr_);
}

void Canvas::save_png(const std::string& path) {
  AtomicOutput out(path);
  cairo_surface_flush(surface_);
  const int width = cairo_image_surface_get_width(surface_), height = cairo_image_surface_get_height(surface_);
  const int stride = cairo_image_surface_get_stride(surface_);
  std::FILE* file = std::fopen(out.temp_path().c_str(), "wb");
  const bool written = file && write_rgb_png(file, cairo_image_surface_get_data(surface_), width, height, stride);
  const bool closed = file && std::fclose(file) == 0;
  if (!written || !closed) throw FormatError(path + ": cannot write the PNG picture (disk full?)");
  out.commit();
}

}  // namespace gesmi::io
