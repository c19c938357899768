#include "report/animation_view.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "report/number_format.hpp"

namespace armstudy::report {
namespace {

using nlohmann::json;

const json& animations(const json& results) {
  static const json empty = json::array();
  return results.is_object() && results.contains("animations") && results["animations"].is_array()
             ? results["animations"]
             : empty;
}

// the loop the page plays: real speed, or slowed to kShortestLoop_s
double loop_seconds(const json& a) {
  const double real = jsonv::num(a, "video_duration_s");
  const double d = std::isfinite(real) && real > 0 ? real : jsonv::num(a, "duration_s");
  return std::isfinite(d) && d >= kShortestLoop_s ? d : kShortestLoop_s;
}

std::string percent(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g%%", v);
  return buf;
}

}  // namespace

std::string animation_class(const std::string& name) {
  std::string out = "a-";
  for (char c : name)
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') out += c;
  return out;
}

Section animation_section(const json& results) {
  Section s;
  s.id = "motion";
  s.heading = "The motion, moving";
  s.new_page = false;
  std::vector<Movie> movies;
  for (const json& a : animations(results)) {
    Movie m;
    m.css_class = animation_class(jsonv::str(a, "name"));
    m.still = jsonv::str(a, "still");
    m.video = a.contains("video") && a["video"].is_string() ? a["video"].get<std::string>() : "";
    m.title = jsonv::str(a, "title");
    const double real = jsonv::num(a, "duration_s"), loop = loop_seconds(a);
    const double fps = jsonv::num(a, "fps");
    const double slow = std::isfinite(jsonv::num(a, "video_duration_s")) ? loop / jsonv::num(a, "video_duration_s") : 1;
    m.caption = jsonv::str(a, "frames") + " frames over " + format_sig(real, 3) + " s (" +
                format_sig(fps, 3) + " per second of the motion), " +
                (slow > 1.001 ? "played " + format_sig(slow, 2) + "× slower than real time"
                              : std::string("played at real speed")) +
                "; hover to pause; printed as its last frame.";
    if (a.contains("note") && a["note"].is_string()) m.caption += " " + a["note"].get<std::string>() + ".";
    if (!m.title.empty()) m.title[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(m.title[0])));
    movies.push_back(std::move(m));
  }
  if (!movies.empty()) {
    s.paragraph("Each motion replayed in MuJoCo at equal time steps. The video files beside "
                "this page play at the motion's real speed, for slides.");
    s.movies(std::move(movies));
  }
  return s;
}

std::string animation_css(const json& results) {
  std::string css;
  for (const json& a : animations(results)) {
    const std::string cls = animation_class(jsonv::str(a, "name"));
    const std::string sprite = jsonv::str(a, "sprite");
    const int n = static_cast<int>(jsonv::num(a, "frames"));
    const int cols = static_cast<int>(jsonv::num(a, "columns"));
    const double w = jsonv::num(a, "frame_width_px"), h = jsonv::num(a, "frame_height_px");
    // the sprite's name comes from the scene (letters, digits, '_', '-', '.'); checked anyway
    const bool safe = !sprite.empty() && std::all_of(sprite.begin(), sprite.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
    });
    if (!safe || n < 2 || cols < 1 || !(w > 0) || !(h > 0)) continue;
    const int rows = (n + cols - 1) / cols;
    char head[512];
    std::snprintf(head, sizeof head,
                  ".anim.%s { aspect-ratio: %g / %g; background-image: url(\"%s\"); "
                  "background-size: %d00%% %d00%%; animation: %s %.4gs step-end infinite; }\n",
                  cls.c_str(), w, h, sprite.c_str(), cols, rows, cls.c_str(), loop_seconds(a));
    css += head;
    css += "@keyframes " + cls + " {";
    for (int k = 0; k <= n; ++k) {
      const int f = std::min(k, n - 1);  // 100%: the last frame, held
      const double x = cols > 1 ? 100.0 * (f % cols) / (cols - 1) : 0;
      const double y = rows > 1 ? 100.0 * (f / cols) / (rows - 1) : 0;
      css += " " + percent(100.0 * k / n) + " { background-position: " + percent(x) + " " + percent(y) + "; }";
    }
    css += " }\n";
  }
  return css;
}

}  // namespace armstudy::report
