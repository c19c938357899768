// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/animation_view.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "report/number_format.hpp"

namespace armstudy::report {
namespace {

// the loop the page plays: real speed, or slowed to kShortestLoop_s
double loop_seconds(const AnimationRecord& a) {
  const double real = a.video_duration_s;
  const double d = std::isfinite(real) && real > 0 ? real : a.duration_s;
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

Section animation_section(const std::vector<AnimationRecord>& animations) {
  Section s;
  s.id = "motion";
  s.heading = "The motion, moving";
  s.new_page = false;
  std::vector<Movie> movies;
  for (const AnimationRecord& a : animations) {
    Movie m;
    m.css_class = animation_class(a.name);
    m.still = a.still;
    m.video = a.video.value_or("");
    m.title = a.title;
    const double real = a.duration_s, loop = loop_seconds(a);
    const double fps = a.fps;
    const double slow = std::isfinite(a.video_duration_s) ? loop / a.video_duration_s : 1;
    m.caption = as_text(a.frames) + " frames over " + format_sig(real, 3) + " s (" +
                format_sig(fps, 3) + " per second of the motion), " +
                (slow > 1.001 ? "played " + format_sig(slow, 2) + "× slower than real time"
                              : std::string("played at real speed")) +
                "; hover to pause; printed as its last frame.";
    if (a.note) m.caption += " " + *a.note + ".";
    if (!m.title.empty())
      m.title[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(m.title[0])));
    movies.push_back(std::move(m));
  }
  if (!movies.empty()) {
    s.paragraph(
        "Each motion replayed in MuJoCo at equal time steps. The video files beside "
        "this page play at the motion's real speed, for slides.");
    s.movies(std::move(movies));
  }
  return s;
}

std::string animation_css(const std::vector<AnimationRecord>& animations) {
  std::string css;
  for (const AnimationRecord& a : animations) {
    const std::string cls = animation_class(a.name);
    const std::string& sprite = a.sprite;
    const int n = a.frames;
    const int cols = a.columns;
    const double w = a.frame_width_px, h = a.frame_height_px;
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
      css += " " + percent(100.0 * k / n) + " { background-position: " + percent(x) + " " +
             percent(y) + "; }";
    }
    css += " }\n";
  }
  return css;
}

}  // namespace armstudy::report
