// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#pragma once
// Headless Chromium for the tests that open pages in a real browser (the case reports, the
// diff page): shell helpers, a run with a fresh profile, and how much ink a screenshot has.

#include <png.h>
#include <sys/wait.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace armstudy::testing {

/// Runs a shell command; returns its exit status (-1 if it did not exit).
inline int run(const std::string& cmd) {
  const int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

/// `s` quoted for the shell.
inline std::string quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

inline const char* kChromiumFlags =
    " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
    " --disable-background-networking --disable-component-update --disable-sync"
    " --disable-extensions --hide-scrollbars";

/// A chromium run with its own fresh profile under `work`; returns the exit status.
inline int chromium(const std::string& args, const std::filesystem::path& work,
                    const std::string& tag) {
  const std::filesystem::path profile = work / ("profile-" + tag);
  std::filesystem::remove_all(profile);
  const std::string cmd = "chromium" + std::string(kChromiumFlags) +
                          " --user-data-dir=" + quote(profile.string()) + " " + args;
  const int rc = run(cmd);
  std::filesystem::remove_all(profile);
  return rc;
}

inline std::string file_url(const std::filesystem::path& p) {
  return "file://" + std::filesystem::absolute(p).string();
}

/// Share of pixels that are not (near) white, over an RGBA image read with libpng; -1 when
/// it cannot be read. `distinct_colours` receives the number of colours (up to 100000).
inline double ink_fraction_png(const std::filesystem::path& png, size_t* distinct_colours) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, png.c_str())) return -1;
  image.format = PNG_FORMAT_RGBA;
  std::vector<png_byte> px(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, px.data(), 0, nullptr)) return -1;
  size_t ink = 0;
  std::set<uint32_t> colours;
  const size_t n = static_cast<size_t>(image.width) * image.height;
  for (size_t i = 0; i < n; ++i) {
    const png_byte* p = &px[4 * i];
    if (p[0] < 235 || p[1] < 235 || p[2] < 235) ++ink;
    if (colours.size() < 100000) colours.insert((p[0] << 16) | (p[1] << 8) | p[2]);
  }
  *distinct_colours = colours.size();
  return n ? static_cast<double>(ink) / n : -1;
}

}  // namespace armstudy::testing

#include <regex>
#include <sstream>

#include "testing/files.hpp"

namespace armstudy::testing {

/// Opens `page` in headless Chromium (--dump-dom, console logged) and returns every problem
/// found: a failed run, no <h1> or no Content-Security-Policy in the built page, a console
/// message (CSP violations, script errors, failed resources), a src/href/data target that
/// points to the network or is missing beside the page. `targets` receives how many local
/// targets the page has.
inline std::vector<std::string> page_problems(const std::filesystem::path& page,
                                              const std::filesystem::path& work,
                                              const std::string& tag, int* targets) {
  static const std::regex kTarget(R"re(\b(?:src|href|data)="([^"]*)")re");
  std::vector<std::string> problems;
  const std::filesystem::path dom = work / ("dom-" + tag + ".html");
  const std::filesystem::path log = work / ("console-" + tag + ".log");
  const int status = chromium("--enable-logging=stderr --v=0 --dump-dom " + quote(file_url(page)) +
                                  " > " + quote(dom.string()) + " 2> " + quote(log.string()),
                              work, tag);
  if (status != 0)
    problems.push_back("chromium exited with " + std::to_string(status) + ": " + slurp(log));
  const std::string html = slurp(dom);
  if (html.find("<h1>") == std::string::npos) problems.push_back("the page has no <h1>");
  if (html.find("Content-Security-Policy") == std::string::npos)
    problems.push_back("no Content-Security-Policy");
  std::istringstream lines(slurp(log));
  std::string line;
  while (std::getline(lines, line))
    if (line.find(":CONSOLE") != std::string::npos) problems.push_back("console: " + line);
  *targets = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), kTarget);
       it != std::sregex_iterator(); ++it) {
    const std::string t = (*it)[1];
    if (t.empty() || t[0] == '#') continue;
    if (t.find("://") != std::string::npos)
      problems.push_back("points to " + t);
    else if (!std::filesystem::exists(page.parent_path() / t))
      problems.push_back("missing " + t);
    ++*targets;
  }
  return problems;
}

}  // namespace armstudy::testing
