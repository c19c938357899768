// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/plot.hpp"

#include "report/svg_compact.hpp"
#include "sys/atomic_file.hpp"

#include <fcntl.h>
#include <locale.h>
#include <plplot/plstream.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace armstudy::report {
namespace fs = std::filesystem;
namespace {

// plplot keeps one global set of streams: one plot at a time in the whole process
std::mutex& plplot_mutex() {
  static std::mutex m;
  return m;
}

// switches this thread to the C locale for the lifetime of the guard
class CLocaleGuard {
 public:
  CLocaleGuard() : c_(newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(0))) {
    if (c_) old_ = uselocale(c_);
  }
  ~CLocaleGuard() {
    if (c_) {
      uselocale(old_);
      freelocale(c_);
    }
  }
  CLocaleGuard(const CLocaleGuard&) = delete;
  CLocaleGuard& operator=(const CLocaleGuard&) = delete;

 private:
  locale_t c_;
  locale_t old_ = static_cast<locale_t>(0);
};

// PLplot's errors. plabort() reports through the abort handler and goes on; plexit() calls
// the exit handler and then exit(1) ("unsolvable" to a caller). The exit handler here
// throws instead, so that a plot PLplot cannot draw ends in a runtime error with a message
// (exit 3). PLplot's state after a plexit is undefined: the stream is leaked, not ended,
// and every later plot is refused with the same message.
std::string& plplot_failure() {  // guarded by plplot_mutex()
  static std::string failure;
  return failure;
}
std::string& plplot_last_abort() {  // guarded by plplot_mutex()
  static std::string text;
  return text;
}

std::string drivers_text() {
  const char* dir = std::getenv("PLPLOT_DRV_DIR");
  return dir ? std::string("PLPLOT_DRV_DIR is '") + dir + "'"
             : std::string("PLPLOT_DRV_DIR is unset: PLplot's default driver folder");
}

// PLplot says "could not open drivers directory" or "unable to load driver" when the
// process is out of file descriptors: that is named when it is the case now
std::string fd_shortage() {
  const int fd = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  if (fd >= 0) {
    ::close(fd);
    return "";
  }
  if (errno != EMFILE && errno != ENFILE) return "";
  struct rlimit rl {};
  ::getrlimit(RLIMIT_NOFILE, &rl);
  return errno == ENFILE ? "; the system is out of file descriptors"
                         : "; armstudy is out of file descriptors (ulimit -n is " +
                               std::to_string(rl.rlim_cur) + ")";
}

std::string plplot_error_text(const std::string& what) {
  return "cannot draw plots: " + what + fd_shortage() + " (" + drivers_text() +
         "); expected PLplot's cairo driver (Debian: plplot-driver-cairo) in the folder that "
         "PLPLOT_DRV_DIR names, or PLPLOT_DRV_DIR unset";
}

int throw_on_plexit(PLCHAR_VECTOR message) {
  std::string m = message ? message : "";
  if (!plplot_last_abort().empty()) m += " after: " + plplot_last_abort();
  plplot_failure() = plplot_error_text("PLplot failed: " + m);
  throw std::runtime_error(plplot_failure());
}

void keep_plabort(PLCHAR_VECTOR message) { plplot_last_abort() = message ? message : ""; }

// true if PLplot lists the device; plinit would otherwise ask for a device on stdin (and
// hang there, or exit(1) after ten tries)
bool device_listed(const char* device) {
  std::vector<const char*> menu(256), names(256);
  const char** m = menu.data();
  const char** n = names.data();
  int count = static_cast<int>(names.size());
  plgDevs(&m, &n, &count);
  for (int i = 0; i < count; ++i)
    if (n[i] && std::strcmp(n[i], device) == 0) return true;
  return false;
}

// called with plplot_mutex() held, before a stream is made: throws if a plot cannot be drawn
void require_device(const char* device) {
  if (!plplot_failure().empty()) throw std::runtime_error(plplot_failure());
  plsexit(throw_on_plexit);
  plsabort(keep_plabort);
  // plabort prints to stderr unless the stream has an error buffer: the handler keeps it
  static PLINT code = 0;
  static char text[1024];
  plsError(&code, text);
  static bool listed = false;  // once listed, it stays (PLplot reads its folder once)
  if (listed) return;
  plplot_last_abort().clear();
  listed = device_listed(device);
  if (!listed) {
    const std::string why = plplot_last_abort().empty() ? "" : " (" + plplot_last_abort() + ")";
    plplot_failure() =
        plplot_error_text(std::string("PLplot has no '") + device + "' device" + why);
    throw std::runtime_error(plplot_failure());
  }
}

// okabe-ito colour-blind-safe palette, then a few darker extras
constexpr Rgb kPalette[] = {{0, 114, 178},  {213, 94, 0},   {0, 158, 115}, {204, 121, 167},
                            {230, 159, 0},  {86, 180, 233}, {120, 94, 60}, {90, 90, 90},
                            {150, 40, 160}, {40, 120, 40}};
constexpr Rgb kBlack{0, 0, 0};
constexpr Rgb kWhite{255, 255, 255};
constexpr Rgb kGrey{110, 110, 110};

// cmap0 slots: 0 background, 1 axes and text, 2.. per drawn item
constexpr int kSlotBackground = 0;
constexpr int kSlotInk = 1;
constexpr int kFirstFreeSlot = 2;

// text for plplot: '#' starts an escape sequence there, so a literal one is doubled
std::string pl_text(const std::string& s) {
  std::string out;
  for (char c : s) {
    out += c;
    if (c == '#') out += '#';
  }
  return out;
}

PLINT style_code(LineStyle s) {
  switch (s) {
    case LineStyle::kDashed: return 3;  // long dashes
    case LineStyle::kDotted: return 2;  // short dashes
    default: return 1;
  }
}

// everything one plot needs from plplot: device, page, white background, colour slots
class Page {
 public:
  Page(const fs::path& svg, int width_pt, int height_pt, int slots)
      : lock_(plplot_mutex()), stream_(make_stream(kDevice)), p(*stream_) {
    // plplot (through cairo) ignores failed writes: it draws into memory here, and the
    // file is written by write_file_atomic, which says why a write fails (disk full, ...)
    mem_ = ::open_memstream(&buf_, &len_);
    if (!mem_) throw std::runtime_error("cannot draw " + svg.string() + ": out of memory");
    try {
      p.sdev(kDevice);
      p.sfile(mem_);
      p.spage(0, 0, width_pt, height_pt, 0, 0);
      p.scolbg(kWhite.r, kWhite.g, kWhite.b);
      p.scmap0n(std::max(16, kFirstFreeSlot + slots));
      p.init();
      p.scol0(kSlotBackground, kWhite.r, kWhite.g, kWhite.b);
      p.scol0(kSlotInk, kBlack.r, kBlack.g, kBlack.b);
      p.col0(kSlotInk);
      p.adv(0);
      p.schr(0, 1.0);
    } catch (...) {
      abandon();
      throw;
    }
  }
  Page(const Page&) = delete;
  Page& operator=(const Page&) = delete;

  // a fresh cmap0 slot holding colour c
  PLINT slot(const Rgb& c) {
    const PLINT s = next_++;
    p.scol0(s, c.r, c.g, c.b);
    return s;
  }

  // closes the stream (which writes the file), compacts it and moves it into place
  void finish(const fs::path& svg) {
    stream_.reset();  // plplot closes mem_: buf_ holds the SVG
    mem_ = nullptr;
    const std::string text = buf_ ? std::string(buf_, len_) : std::string();
    if (text.find("</svg>") == std::string::npos)
      throw std::runtime_error("plplot drew no complete SVG for " + svg.string());
    sys::write_file_atomic(svg, compact_svg(text));
  }

  ~Page() {
    if (!plplot_failure().empty()) {
      abandon();
      return;
    }
    stream_.reset();  // (closes mem_ when finish() was not reached)
    std::free(buf_);
  }

 private:
  static constexpr const char* kDevice = "svgcairo";

  static std::unique_ptr<plstream> make_stream(const char* device) {
    require_device(device);
    return std::make_unique<plstream>();
  }
  // after a plexit: PLplot's stream is left as it is (ending it may fail again)
  void abandon() {
    (void)stream_.release();
    if (mem_) std::fclose(mem_);
    mem_ = nullptr;
    std::free(buf_);
    buf_ = nullptr;
  }

  std::lock_guard<std::mutex> lock_;
  CLocaleGuard locale_;
  std::unique_ptr<plstream> stream_;

 public:
  plstream& p;  // the open stream (valid until finish)

 private:
  FILE* mem_ = nullptr;  // plplot's output, closed by plplot
  char* buf_ = nullptr;
  size_t len_ = 0;
  PLINT next_ = kFirstFreeSlot;
};

// draws x/y as polylines, split at non-finite points
void draw_polyline(plstream& p, const std::vector<double>& x, const std::vector<double>& y,
                   bool log_y) {
  std::vector<PLFLT> px, py;
  auto flush = [&] {
    if (px.size() >= 2) p.line(static_cast<PLINT>(px.size()), px.data(), py.data());
    px.clear();
    py.clear();
  };
  for (size_t k = 0; k < x.size(); ++k) {
    double yy = log_y ? (y[k] > 0 ? std::log10(y[k]) : NAN) : y[k];
    if (!std::isfinite(x[k]) || !std::isfinite(yy)) {
      flush();
      continue;
    }
    px.push_back(x[k]);
    py.push_back(yy);
  }
  flush();
}

void draw_markers(plstream& p, const std::vector<double>& x, const std::vector<double>& y,
                  bool log_y) {
  for (size_t k = 0; k < x.size(); ++k) {
    PLFLT px = x[k], py = log_y ? (y[k] > 0 ? std::log10(y[k]) : NAN) : y[k];
    if (std::isfinite(px) && std::isfinite(py)) p.poin(1, &px, &py, 4);
  }
}

// legend entries, kept alive for pllegend's const char* arrays
struct LegendEntries {
  std::vector<PLINT> opt, text_colors, box_colors, box_patterns, line_colors, line_styles,
      symbol_colors, symbol_numbers;
  std::vector<PLFLT> box_scales, box_line_widths, line_widths, symbol_scales;
  std::vector<std::string> text, symbols;

  void add(const std::string& label, PLINT colour, PLINT kind, PLINT style, PLFLT width,
           const char* symbol) {
    opt.push_back(kind);
    text.push_back(pl_text(label));
    text_colors.push_back(kSlotInk);
    box_colors.push_back(colour);
    box_patterns.push_back(0);
    box_scales.push_back(0.8);
    box_line_widths.push_back(1);
    line_colors.push_back(colour);
    line_styles.push_back(style);
    line_widths.push_back(width);
    symbol_colors.push_back(colour);
    symbol_scales.push_back(1.0);
    symbol_numbers.push_back(1);
    symbols.push_back(symbol);
  }

  void draw(plstream& p, PLINT position, PLFLT x, PLFLT y, PLINT columns) {
    if (opt.empty()) return;
    std::vector<const char*> t, s;
    for (auto& e : text) t.push_back(e.c_str());
    for (auto& e : symbols) s.push_back(e.c_str());
    const PLINT n = static_cast<PLINT>(opt.size());
    const PLINT rows = (n + columns - 1) / columns;
    PLFLT w = 0, h = 0;
    p.legend(&w, &h, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX | PL_LEGEND_ROW_MAJOR, position,
             x, y, 0.07, kSlotBackground, kSlotInk, 1, rows, columns, n, opt.data(), 0.8, 0.8, 2.0,
             0.0, text_colors.data(), t.data(), box_colors.data(), box_patterns.data(),
             box_scales.data(), box_line_widths.data(), line_colors.data(), line_styles.data(),
             line_widths.data(), symbol_colors.data(), symbol_scales.data(), symbol_numbers.data(),
             s.data());
  }
};

void check_series(const Series& s) {
  if (s.x.size() != s.y.size())
    throw std::invalid_argument("plot series '" + s.label + "' has " + std::to_string(s.x.size()) +
                                " x values and " + std::to_string(s.y.size()) +
                                " y values; expected equal sizes");
}

// padded [lo, hi] that is never empty
void widen(double* lo, double* hi, double pad_fraction) {
  if (!(*hi > *lo)) {
    const double m = std::max(1.0, std::abs(*lo)) * 0.05;
    *lo -= m;
    *hi += m;
    return;
  }
  const double pad = (*hi - *lo) * pad_fraction;
  *lo -= pad;
  *hi += pad;
}

// a 1-2-5 step giving at most max_ticks intervals over range
double nice_step(double range, double max_ticks) {
  if (!(range > 0) || !(max_ticks >= 1)) return 0;
  const double raw = range / max_ticks;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * mag >= raw) return m * mag;
  return 10 * mag;
}

// axes with at most one labelled tick per ~50 pt of viewport width, ~30 pt of height
void draw_box(plstream& p, int width_pt, int height_pt, double x_range, double y_range,
              bool log_y) {
  PLFLT vx0, vx1, vy0, vy1;
  p.gvpd(vx0, vx1, vy0, vy1);
  const double xt = nice_step(x_range, std::max(2.0, (vx1 - vx0) * width_pt / 50));
  const double yt = log_y ? 0 : nice_step(y_range, std::max(2.0, (vy1 - vy0) * height_pt / 30));
  // fixed-point numbers with the decimals the tick step needs: plplot's own choice puts a
  // "(x10^k)" over the axis that the page's edge cuts off (line plots scale their values
  // into a readable range first, see write_line_plot)
  auto decimals = [](double step) {
    return step > 0 ? std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9))) : 2;
  };
  p.prec(1, decimals(xt));
  p.box("bcnstf", xt, 0, "", 0, 0);
  p.prec(1, decimals(yt));
  p.box("", 0, 0, log_y ? "bcnstvl" : "bcnstvf", yt, 0);
  p.prec(0, 0);
}

// the number of characters of the widest y tick label draw_box writes for [lo, hi] in steps
// of `step` (a log axis writes powers of ten, about four characters)
int widest_tick_label(double lo, double hi, double step, bool log_y) {
  if (log_y || !(step > 0)) return 4;
  const int decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
  int widest = 1;
  char buf[64];
  for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; k += 1) {
    const double v = std::abs(k * step) < 1e-12 * step ? 0.0 : k * step;
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    widest = std::max(widest, static_cast<int>(std::strlen(buf)));
  }
  return widest;
}

// axis labels and title; the y label clear of the widest y tick label (plplot's own place,
// five character heights out, ran into labels such as "-0.015")
double y_label_offset(int widest_tick) { return std::max(5.0, 0.8 * widest_tick + 1.4); }
void draw_labels(plstream& p, const std::string& x, const std::string& y, const std::string& title,
                 double y_offset) {
  p.mtex("b", 3.2, 0.5, 0.5, pl_text(x).c_str());
  p.mtex("l", y_offset, 0.5, 0.5, pl_text(y).c_str());
  p.mtex("t", 2.0, 0.5, 0.5, pl_text(title).c_str());
}
// the left edge of the viewport (a fraction of the page) that leaves room for the y label
double left_edge_for(plstream& p, double y_offset) {
  PLFLT def = 0, ht = 0, x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  p.gchr(def, ht);
  p.gspa(x0, x1, y0, y1);
  return x1 > x0 ? (y_offset + 1.0) * ht / (x1 - x0) : 0;
}

// "10⁻¹³": a power of ten with its exponent in superscript digits (drawn in full, unlike
// plplot's own "(x10^k)" over the axis, which the page's top edge cut off)
std::string power_of_ten(int k) {
  static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string e = std::to_string(std::abs(k)), out = "10";
  if (k < 0) out += "⁻";
  for (char c : e) out += digits[c - '0'];
  return out;
}

// the exponent that brings values of magnitude up to `m` into [1, 1000), 0 when they are
// readable as they are (0.01 .. 99999)
int axis_exponent(double m) {
  if (!(m > 0) || !std::isfinite(m) || (m >= 1e-2 && m < 1e5)) return 0;
  return static_cast<int>(std::floor(std::log10(m)));
}

// "E (J)" with values scaled by 10^-k -> "E (10⁻¹³ J)"; no unit: "E (×10⁻¹³)"
std::string scaled_label(const std::string& label, int k) {
  if (k == 0) return label;
  const size_t open = label.rfind(" (");
  if (!label.empty() && label.back() == ')' && open != std::string::npos)
    return label.substr(0, open + 2) + power_of_ten(k) + " " + label.substr(open + 2);
  return label + " (×" + power_of_ten(k) + ")";
}

// the map being shaded, for plplot's "defined" callback (which carries no user data);
// only touched while the plplot mutex is held
const ShadedMap* g_defined_map = nullptr;

PLINT map_defined(PLFLT x, PLFLT y) {
  const ShadedMap& m = *g_defined_map;
  const double dx = m.nx > 1 ? (m.x_max - m.x_min) / (m.nx - 1) : 1;
  const double dy = m.ny > 1 ? (m.y_max - m.y_min) / (m.ny - 1) : 1;
  const long i = std::lround((x - m.x_min) / dx);
  const long j = std::lround((y - m.y_min) / dy);
  if (i < 0 || j < 0 || i >= m.nx || j >= m.ny) return 0;
  return std::isfinite(m.z[static_cast<size_t>(j) * m.nx + i]) ? 1 : 0;
}

// viridis, sampled at five points (perceptually uniform, prints in grey)
void set_viridis(plstream& p) {
  PLFLT pos[] = {0, 0.25, 0.5, 0.75, 1};
  PLFLT r[] = {68 / 255.0, 59 / 255.0, 33 / 255.0, 94 / 255.0, 253 / 255.0};
  PLFLT g[] = {1 / 255.0, 82 / 255.0, 145 / 255.0, 201 / 255.0, 231 / 255.0};
  PLFLT b[] = {84 / 255.0, 139 / 255.0, 140 / 255.0, 98 / 255.0, 37 / 255.0};
  p.scmap1n(256);
  p.scmap1l(true, 5, pos, r, g, b, nullptr);
}

}  // namespace

Rgb colour_for(std::string_view key) {
  static const std::map<std::string, Rgb, std::less<>> known = {
      {"cycloidal/1", kPalette[0]},
      {"cycloidal/2", kPalette[1]},
      {"poly345/1", kPalette[2]},
      {"poly345/2", kPalette[3]},
      {"reachability", kPalette[0]},
      {"dp", kPalette[1]},
      {"complex", kPalette[2]},
      {"mvc", kBlack},
      {"initial", kPalette[7]},
      {"idp", kPalette[0]},
      {"gradient", kPalette[1]},
      {"joint1", kPalette[0]},
      {"joint2", kPalette[1]},
      {"joint3", kPalette[2]},
      {"joint4", kPalette[3]},
      {"limit", kGrey},
      {"energy", kPalette[0]},
      {"kinetic", kPalette[1]},
      {"potential", kPalette[2]},
      {"mechanical", kBlack},
      // a source's printed placements of configuration 1 and 2 (report/placement_printed.cpp)
      {"printed/1", kPalette[8]},
      {"printed/2", kPalette[6]},
  };
  if (auto it = known.find(key); it != known.end()) return it->second;
  // fnv-1a: stable across runs and machines, unlike std::hash
  std::uint32_t h = 2166136261u;
  for (char ch : key) h = (h ^ static_cast<unsigned char>(ch)) * 16777619u;
  return kPalette[4 + h % 6];
}

std::vector<Rgb> palette_colours() {
  std::vector<Rgb> out(std::begin(kPalette), std::end(kPalette));
  out.push_back(kBlack);
  out.push_back(kGrey);
  return out;
}

std::string css_colour(const Rgb& c) {
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}

// (over 60 lines, kept whole: one PLplot page drawn in order: the stream's viewport, window and
// colours carry from step to step)
void write_line_plot(const LinePlot& input, const fs::path& svg) {
  // values far from 1 are drawn scaled, the power of ten written into the axis label
  LinePlot plot = input;
  {
    double mx = 0, my = 0;
    for (const auto& s : plot.series) {
      check_series(s);
      for (size_t k = 0; k < s.x.size(); ++k)
        if (std::isfinite(s.x[k]) && std::isfinite(s.y[k])) {
          mx = std::max(mx, std::abs(s.x[k]));
          my = std::max(my, std::abs(s.y[k]));
        }
    }
    for (const auto& r : plot.references)
      if (std::isfinite(r.y)) my = std::max(my, std::abs(r.y));
    const int kx = axis_exponent(mx), ky = plot.log_y ? 0 : axis_exponent(my);
    const double fx = std::pow(10.0, -kx), fy = std::pow(10.0, -ky);
    for (auto& s : plot.series) {
      for (double& v : s.x) v *= fx;
      for (double& v : s.y) v *= fy;
    }
    for (auto& r : plot.references) r.y *= fy;
    plot.x_label = scaled_label(plot.x_label, kx);
    plot.y_label = scaled_label(plot.y_label, ky);
  }
  double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
  for (const auto& s : plot.series) {
    check_series(s);
    for (size_t k = 0; k < s.x.size(); ++k) {
      const double y = plot.log_y ? (s.y[k] > 0 ? std::log10(s.y[k]) : NAN) : s.y[k];
      if (!std::isfinite(s.x[k]) || !std::isfinite(y)) continue;
      x_lo = std::min(x_lo, s.x[k]);
      x_hi = std::max(x_hi, s.x[k]);
      y_lo = std::min(y_lo, y);
      y_hi = std::max(y_hi, y);
    }
  }
  if (!std::isfinite(x_lo))
    throw std::invalid_argument("plot '" + plot.title + "' has no finite point to draw");
  for (const auto& r : plot.references) {
    const double y = plot.log_y ? std::log10(r.y) : r.y;
    if (std::isfinite(y)) {
      y_lo = std::min(y_lo, y);
      y_hi = std::max(y_hi, y);
    }
  }
  if (!(x_hi > x_lo)) widen(&x_lo, &x_hi, 0);
  widen(&y_lo, &y_hi, 0.06);

  bool has_legend = false;
  for (const auto& s : plot.series) has_legend |= !s.label.empty();
  has_legend |= !plot.references.empty();

  // legend below the axes, two columns: its rows add to the page height
  size_t entries = plot.references.size();
  for (const auto& s : plot.series) entries += !s.label.empty();
  const int columns = entries > 1 ? 2 : 1;
  const int legend_rows = static_cast<int>((entries + columns - 1) / columns);
  const double legend_pt = has_legend ? 14.0 * legend_rows + 14 : 0;
  const int height_pt = plot.height_pt + static_cast<int>(legend_pt);
  Page page(svg, plot.width_pt, height_pt,
            static_cast<int>(plot.series.size() + plot.references.size()));
  plstream& p = page.p;
  const double bottom = (44.0 + legend_pt) / height_pt, top = 1 - 26.0 / height_pt;
  // the y ticks draw_box will write (the same step: it depends on the viewport's height only)
  const double y_step =
      plot.log_y ? 0 : nice_step(y_hi - y_lo, std::max(2.0, (top - bottom) * height_pt / 30));
  const double y_offset = y_label_offset(widest_tick_label(y_lo, y_hi, y_step, plot.log_y));
  p.vpor(std::max(0.11, left_edge_for(p, y_offset)), 0.96, bottom, top);
  p.wind(x_lo, x_hi, y_lo, y_hi);
  p.col0(kSlotInk);
  p.width(0.8);
  p.lsty(1);
  draw_box(p, plot.width_pt, height_pt, x_hi - x_lo, y_hi - y_lo, plot.log_y);
  // light grid for reading values off
  p.scol0(kSlotBackground, kWhite.r, kWhite.g, kWhite.b);
  draw_labels(p, plot.x_label, plot.y_label, plot.title, y_offset);

  LegendEntries legend;
  for (const auto& s : plot.series) {
    const PLINT c = page.slot(s.colour);
    p.col0(c);
    p.width(s.width);
    p.lsty(style_code(s.style));
    draw_polyline(p, s.x, s.y, plot.log_y);
    if (s.markers) {
      p.lsty(1);
      draw_markers(p, s.x, s.y, plot.log_y);
    }
    if (!s.label.empty())
      legend.add(s.label, c, PL_LEGEND_LINE | (s.markers ? PL_LEGEND_SYMBOL : 0),
                 style_code(s.style), s.width, "•");
  }
  for (const auto& r : plot.references) {
    const PLINT c = page.slot(kGrey);
    p.col0(c);
    p.width(1.0);
    p.lsty(2);
    const double y = plot.log_y ? std::log10(r.y) : r.y;
    if (!std::isfinite(y)) continue;
    PLFLT xs[2] = {x_lo, x_hi}, ys[2] = {y, y};
    p.line(2, xs, ys);
    if (!r.label.empty()) legend.add(r.label, c, PL_LEGEND_LINE, 2, 1.0, "");
  }
  p.lsty(1);
  p.width(0.8);
  // offsets are fractions of the viewport: clear the axis numbers and label (~40 pt)
  legend.draw(p, PL_POSITION_OUTSIDE | PL_POSITION_BOTTOM, 0.0, 40.0 / ((top - bottom) * height_pt),
              columns);
  page.finish(svg);
}

namespace {

// @throws std::invalid_argument unless the grid, the masks and the overlays fit together
void check_shaded_map(const ShadedMap& map) {
  const size_t n = static_cast<size_t>(map.nx) * static_cast<size_t>(map.ny);
  if (map.nx < 2 || map.ny < 2 || map.z.size() != n)
    throw std::invalid_argument("map '" + map.title + "' needs nx, ny >= 2 and nx*ny z values");
  for (const auto& r : map.regions)
    if (r.mask.size() != n)
      throw std::invalid_argument("map region '" + r.label + "' needs nx*ny mask values");
  for (const auto& s : map.overlays) check_series(s);
}

// the map's markers: secondary ones (squares) first, then a source's printed points
// (triangles), the primary ones (optima) on top
void draw_map_markers(const ShadedMap& map, Page& page, LegendEntries& legend) {
  plstream& p = page.p;
  const auto pass_of = [](const Marker& m) { return m.printed ? 1 : m.primary ? 2 : 0; };
  for (int pass = 0; pass < 3; ++pass)
    for (const auto& m : map.markers) {
      if (pass_of(m) != pass) continue;
      const PLINT c = page.slot(m.colour);
      PLFLT x = m.x, y = m.y;
      const char* glyph = m.printed ? "△" : m.primary ? "⊗" : "□";
      p.schr(0, m.printed ? 1.6 : m.primary ? 2.2 : 1.2);
      p.col0(c);
      p.string(1, &x, &y, glyph);
      p.schr(0, 1.0);
      if (!m.label.empty()) legend.add(m.label, c, PL_LEGEND_SYMBOL, 1, 1, glyph);
    }
}

// the colour bar of the value field, at its shading levels
void draw_map_colorbar(const ShadedMap& map, plstream& p, const std::vector<PLFLT>& levels) {
  PLINT label_opts[] = {PL_COLORBAR_LABEL_RIGHT};
  const std::string z_label = pl_text(map.z_label);
  const char* labels[] = {z_label.c_str()};
  const char* axis_opts[] = {"bcvtm"};
  PLFLT ticks[] = {0.0};
  PLINT sub_ticks[] = {0};
  PLINT n_values[] = {static_cast<PLINT>(levels.size())};
  const PLFLT* values[] = {levels.data()};
  PLFLT w = 0, h = 0;
  p.colorbar(&w, &h, PL_COLORBAR_SHADE | PL_COLORBAR_SHADE_LABEL, 0, 0.015, 0.0, 0.04, 1.0,
             kSlotBackground, kSlotInk, 1, 0.0, 0.0, 0, 0.0, 1, label_opts, labels, 1, axis_opts,
             ticks, sub_ticks, n_values, values);
}

}  // namespace

// (over 60 lines, kept whole: one PLplot page drawn in order: the stream's viewport, window and
// colours carry from step to step)
void write_shaded_map(const ShadedMap& map, const fs::path& svg) {
  check_shaded_map(map);
  const size_t n = static_cast<size_t>(map.nx) * static_cast<size_t>(map.ny);

  double z_lo = INFINITY, z_hi = -INFINITY;
  for (double z : map.z)
    if (std::isfinite(z)) {
      z_lo = std::min(z_lo, z);
      z_hi = std::max(z_hi, z);
    }
  const bool has_values = std::isfinite(z_lo);
  if (has_values && !(z_hi > z_lo)) widen(&z_lo, &z_hi, 0);

  const double dx = (map.x_max - map.x_min) / (map.nx - 1);
  const double dy = (map.y_max - map.y_min) / (map.ny - 1);
  // a grid's cells reach half a cell past the first and last centres; a drawing with no
  // grid (curves and markers only) spans exactly the given range
  const bool gridded = has_values || !map.regions.empty();
  const double wx0 = gridded ? map.x_min - dx / 2 : map.x_min;
  const double wx1 = gridded ? map.x_max + dx / 2 : map.x_max;
  const double wy0 = gridded ? map.y_min - dy / 2 : map.y_min;
  const double wy1 = gridded ? map.y_max + dy / 2 : map.y_max;

  // plplot's matrices are a[i][j], i along x
  auto grid = [&](const std::function<double(size_t)>& at) {
    std::vector<PLFLT> data(n);
    for (int i = 0; i < map.nx; ++i)
      for (int j = 0; j < map.ny; ++j)
        data[static_cast<size_t>(i) * map.ny + j] = at(static_cast<size_t>(j) * map.nx + i);
    return data;
  };
  auto rows = [&](std::vector<PLFLT>& data) {
    std::vector<const PLFLT*> r(map.nx);
    for (int i = 0; i < map.nx; ++i) r[i] = data.data() + static_cast<size_t>(i) * map.ny;
    return r;
  };

  // legend below, two columns: its rows add to the page height
  size_t entries = map.regions.size();
  for (const auto& o : map.overlays) entries += !o.label.empty();
  for (const auto& m : map.markers) entries += !m.label.empty();
  const double legend_pt = entries ? 14.0 * ((entries + 1) / 2) + 14 : 0;
  const double aspect = map.equal_aspect ? (wy1 - wy0) / (wx1 - wx0) : 0.8;
  // the viewport box below spans 0.70 of the width; 84 pt go to the title, axis numbers
  // and label; a fitted drawing is as tall as the aspect needs (at least 160 pt of plot)
  int body_pt = map.height_pt - 60;
  if (map.fit_height && std::isfinite(aspect) && aspect > 0)
    body_pt = std::clamp(static_cast<int>(std::ceil(0.70 * map.width_pt * aspect)) + 84, 160 + 84,
                         body_pt);
  const int height_pt = body_pt + static_cast<int>(legend_pt);
  Page page(svg, map.width_pt, height_pt,
            static_cast<int>(map.regions.size() + map.overlays.size() + map.markers.size()));
  plstream& p = page.p;
  p.vpas(0.10, 0.80, (50.0 + legend_pt) / height_pt, 1 - 34.0 / height_pt, aspect);
  double y_offset = 5.0;
  {
    // the y label clear of the y ticks draw_box will write: the box moves right if need be
    PLFLT vx0, vx1, vy0, vy1;
    p.gvpd(vx0, vx1, vy0, vy1);
    const double step = nice_step(wy1 - wy0, std::max(2.0, (vy1 - vy0) * height_pt / 30));
    y_offset = y_label_offset(widest_tick_label(wy0, wy1, step, false));
    const double need = left_edge_for(p, y_offset);
    if (need > vx0)
      p.vpas(0.10 + (need - vx0), 0.80, (50.0 + legend_pt) / height_pt, 1 - 34.0 / height_pt,
             aspect);
  }
  p.wind(wx0, wx1, wy0, wy1);
  set_viridis(p);

  LegendEntries legend;
  // the value field, only where it is defined
  std::vector<PLFLT> levels;
  if (has_values) {
    std::vector<PLFLT> zdata =
        grid([&](size_t k) { return std::isfinite(map.z[k]) ? map.z[k] : z_lo; });
    auto zrows = rows(zdata);
    const int nl = std::max(2, map.levels + 1);
    for (int k = 0; k < nl; ++k) levels.push_back(z_lo + (z_hi - z_lo) * k / (nl - 1));
    g_defined_map = &map;
    p.shades(zrows.data(), map.nx, map.ny, map_defined, map.x_min, map.x_max, map.y_min, map.y_max,
             levels.data(), nl, 1.0, 0, 0, plcallback::fill, 1, nullptr, nullptr);
    g_defined_map = nullptr;
  }
  // flat regions over it (a mask's edge lies half a cell out, where the contour of 0.5 is)
  for (const auto& r : map.regions) {
    std::vector<PLFLT> mdata = grid([&](size_t k) { return r.mask[k] ? 1.0 : 0.0; });
    auto mrows = rows(mdata);
    const PLINT c = page.slot(r.colour);
    p.shade(mrows.data(), map.nx, map.ny, nullptr, map.x_min, map.x_max, map.y_min, map.y_max, 0.5,
            1.5, 0, c, 1.0, 0, 0, 0, 0, plcallback::fill, 1, nullptr, nullptr);
    legend.add(r.label, c, PL_LEGEND_COLOR_BOX, 1, 1, "");
  }
  for (const auto& s : map.overlays) {
    const PLINT c = page.slot(s.colour);
    p.col0(c);
    p.width(s.width);
    p.lsty(style_code(s.style));
    draw_polyline(p, s.x, s.y, false);
    if (!s.label.empty()) legend.add(s.label, c, PL_LEGEND_LINE, style_code(s.style), s.width, "");
  }
  p.lsty(1);
  draw_map_markers(map, page, legend);
  p.col0(kSlotInk);
  p.width(0.8);
  draw_box(p, map.width_pt, height_pt, wx1 - wx0, wy1 - wy0, false);
  draw_labels(p, map.x_label, map.y_label, map.title, y_offset);

  if (has_values) draw_map_colorbar(map, p, levels);
  {
    PLFLT vx0, vx1, vy0, vy1;
    p.gvpd(vx0, vx1, vy0, vy1);
    legend.draw(p, PL_POSITION_OUTSIDE | PL_POSITION_BOTTOM, 0.0, 40.0 / ((vy1 - vy0) * height_pt),
                2);
  }
  page.finish(svg);
}

}  // namespace armstudy::report
