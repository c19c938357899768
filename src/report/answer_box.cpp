// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/answer_box.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "report/number_format.hpp"
#include "report/page.hpp"
#include "report/results_record.hpp"
#include "report/source_comparison.hpp"

namespace armstudy::report {
namespace {

std::string joined(const std::vector<std::string>& v, const std::string& sep) {
  std::string s;
  for (const auto& e : v) s += (s.empty() ? "" : sep) + e;
  return s;
}

}  // namespace

std::string check_label(const std::string& name) {
  std::string out;
  std::stringstream in(name);
  std::string part;
  while (std::getline(in, part, '.')) {
    std::string words = part;
    std::replace(words.begin(), words.end(), '_', ' ');
    out += (out.empty() ? "" : ", ") + words;
  }
  // a few proper names
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"mujoco", "MuJoCo"},
                                 {"idp", "IDP"},
                                 {"slsqp", "SLSQP"},
                                 {"nlopt", "NLopt"}}) {
    for (size_t p = out.find(from); p != std::string::npos; p = out.find(from, p + to.size())) {
      const bool start = p == 0 || !std::isalnum(static_cast<unsigned char>(out[p - 1]));
      const bool end = p + from.size() == out.size() ||
                       !std::isalnum(static_cast<unsigned char>(out[p + from.size()]));
      if (start && end) out.replace(p, from.size(), to);
    }
  }
  if (!out.empty()) out[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(out[0])));
  return out;
}

AnswerBox answer_box(const nlohmann::json& results, const CasePage& page, StudyAnswer study) {
  const ResultsRecord record = read_record(results);
  AnswerBox a;
  a.sentence = record.message;  // the study's own words, unchanged
  a.figures = page.key_figures;
  // what binds and what the case assumes, in the study's words; the study may name its key
  // picture (the locus of the motion that answers)
  if (study) study(results, record, a);
  if (record.source) a.source = source_summary(*record.source);

  // else the first locus, else the first strip, else the page's first figure
  auto pick = [&](auto pred) {
    for (const auto& f : record.frames)
      if (pred(f)) return f;
    return std::string();
  };
  if (a.picture.empty())
    a.picture = pick([](const std::string& f) { return f.ends_with("_locus.png"); });
  if (a.picture.empty())
    a.picture = pick([](const std::string& f) { return f.ends_with("_strip.png"); });
  if (!a.picture.empty()) {
    a.picture_caption =
        a.picture.ends_with("_locus.png")
            ? "The motion that answers, replayed in MuJoCo: every pose superimposed, "
              "the oldest faintest."
            : "The motion that answers, replayed in MuJoCo: frames at equal time steps.";
  } else {
    for (const Section& s : page.sections)
      for (const Block& b : s.blocks)
        if (a.picture.empty() && b.kind == Block::Kind::kFigure && !b.figure.file.empty()) {
          a.picture = b.figure.file;
          a.picture_caption = b.figure.caption;
        }
  }

  // the verdict of the checks
  const int total = static_cast<int>(record.checks.size());
  int failed = 0;
  std::vector<std::string> failures;
  for (const CheckRecord& c : record.checks)
    if (!c.passed) {
      ++failed;
      failures.push_back(check_label(c.name));
    }
  a.verdict_ok = failed == 0;
  if (total == 0)
    a.verdict = "The study ran no checks on this case.";
  else if (failed == 0)
    a.verdict = total == 1 ? "The study's check passed."
                           : "All " + std::to_string(total) + " checks passed.";
  else
    a.verdict = std::to_string(failed) + " of " + std::to_string(total) +
                " checks FAILED: " + joined(failures, "; ") + ".";
  return a;
}

}  // namespace armstudy::report
