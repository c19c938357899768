#include "report/answer_box.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

#include "report/number_format.hpp"
#include "report/page.hpp"

namespace armstudy::report {
namespace {

using nlohmann::json;

const json& arr(const json& j, const char* key) {
  static const json empty = json::array();
  return j.is_object() && j.contains(key) && j[key].is_array() ? j[key] : empty;
}
const json& obj(const json& j, const char* key) {
  static const json empty = json::object();
  return j.is_object() && j.contains(key) && j[key].is_object() ? j[key] : empty;
}

std::string joined(const std::vector<std::string>& v, const std::string& sep) {
  std::string s;
  for (const auto& e : v) s += (s.empty() ? "" : sep) + e;
  return s;
}

// ---- what binds ----

std::string binding_words(const json& d) {
  const std::string b = jsonv::str(d, "binding");
  const std::string margin = jsonv::sig(d, "margin_m", 3) + " m";
  if (b == "interior")
    return "interior, nothing binds (clearances beyond the " + margin + " margin: " +
           jsonv::sig(d, "inner_slack_m", 3) + " m inner, " + jsonv::sig(d, "outer_slack_m", 3) + " m outer)";
  if (b == "inner_clearance") return "the " + margin + " clearance margin to the inner circle (a setting)";
  if (b == "outer_clearance") return "the " + margin + " clearance margin to the outer circle (a setting)";
  if (b == "torque_limit") return "the torque limit of joint " + jsonv::str(d, "joint") + " binds";
  if (b == "power_limit") return "the power limit of joint " + jsonv::str(d, "joint") + " binds";
  return b.empty() ? "not reported" : b;
}

void placement(const json& results, AnswerBox& a) {
  const json& pl = obj(results, "placement");
  for (const json& o : arr(pl, "optima")) {
    const std::string who = jsonv::str(o, "program") + " " + jsonv::str(o, "configuration");
    a.binding.push_back(who + ": " + binding_words(obj(o, "decided_by")));
  }
  for (const json& u : arr(pl, "unsolved"))
    a.binding.push_back(jsonv::str(u, "program") + ", configuration " + jsonv::str(u, "configuration") +
                        ": no optimum (" + jsonv::str(u, "reason") + ")");
  a.assumptions.push_back("energy integral (8.1): " + jsonv::str(pl, "samples") +
                          " samples, doubled until it changes by < 1e-4");
  a.assumptions.push_back("singular: a line within " + jsonv::sig(pl, "singularity_margin_m", 3) +
                          " m of the annulus' boundary (a setting)");
  const bool tl = jsonv::has(pl, "torque_limits_Nm") && !pl["torque_limits_Nm"].is_null();
  const bool plim = jsonv::has(pl, "power_limits_W") && !pl["power_limits_W"].is_null();
  a.assumptions.push_back(tl || plim ? "actuator limits as the case gives them"
                                     : "no actuator limits (any torque, as in the thesis)");
  a.assumptions.push_back("rest to rest, zero end accelerations; no actuator masses (as the thesis)");
}

void pendulum(const json& results, AnswerBox& a) {
  const json& pe = obj(results, "pendulum");
  a.binding.push_back("no optimum: a free swing of the passive tray and ball, checked by the "
                      "conservation of its mechanical energy (drift " +
                      jsonv::sig(obj(pe, "energy"), "drift_relative", 3) + " of the energy exchanged, "
                      "tolerance " + jsonv::sig(obj(pe, "energy"), "tolerance_relative", 2) + ")");
  for (const json& c : arr(obj(pe, "parameters"), "choices"))
    if (c.is_string()) a.assumptions.push_back(c.get<std::string>());
}

std::string constraint_words(const std::string& c) {
  if (c == "contact") return "contact force";
  if (c == "friction") return "friction needed";
  if (c == "tray") return "ball within the tray";
  if (c == "release") return "release angle";
  return c;
}

void throwing(const json& results, AnswerBox& a) {
  const json& th = obj(results, "throwing");
  for (const json& row : arr(th, "comparison")) {
    std::vector<std::string> b;
    for (const json& n : arr(row, "binding"))
      if (n.is_string()) b.push_back(constraint_words(n.get<std::string>()));
    a.binding.push_back(jsonv::str(row, "optimiser") + ": " +
                        (b.empty() ? "no constraint binds" : joined(b, ", ") + " bind") +
                        "; motor rating nearest its limit: " + jsonv::str(row, "binding_rating"));
  }
  for (const json& x : arr(th, "assumptions")) {
    const std::string unit = jsonv::str(x, "unit");
    a.assumptions.push_back(jsonv::str(x, "name") + ": " + jsonv::sig(x, "value", 4) +
                            (unit.empty() ? "" : " " + unit));
  }
}

// the share of the exact solver's samples at which each limit is within 1 % of its bound
void time_optimal(const json& results, AnswerBox& a) {
  const json& to = obj(results, "time_optimal");
  const json& lim = obj(to, "limits");
  const json& solvers = arr(to, "solvers");
  if (!solvers.empty()) {
    const json& s = obj(solvers[0], "samples");
    const size_t n = arr(s, "t_s").size();
    struct Kind {
      const char* key;
      const char* limit;
      const char* words;
    };
    std::vector<std::pair<double, std::string>> shares;
    for (const Kind& k : {Kind{"tau_Nm", "torque_Nm", "torque"},
                          Kind{"qd_rad_s", "velocity_rad_s", "velocity"},
                          Kind{"qdd_rad_s2", "acceleration_rad_s2", "acceleration"}}) {
      const auto l = jsonv::vec(lim, k.limit);
      for (size_t j = 0; j < l.size() && n > 0; ++j) {
        const auto v = jsonv::column(s, k.key, j, n);
        if (v.size() != n || !(l[j] > 0)) continue;
        size_t at = 0;
        for (double x : v) at += std::isfinite(x) && std::abs(x) >= 0.99 * l[j];
        if (at > 0)
          shares.push_back({double(at) / n, std::string(k.words) + " of joint " + std::to_string(j + 1)});
      }
    }
    std::sort(shares.begin(), shares.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
    for (const auto& [share, what] : shares)
      a.binding.push_back("the " + what + " limit binds at " + format_sig(100 * share, 2) +
                          " % of the samples (within 1 %)");
    if (shares.empty() && n > 0) a.binding.push_back("no limit is within 1 % of its bound at any sample");
  }
  const std::string path = jsonv::str(obj(to, "path"), "kind");
  if (jsonv::str(obj(to, "path"), "space") == "joint") {
    if (!path.empty())
      a.assumptions.push_back("the joints follow the given joint-space path (" + path +
                              "), parametrised by its chord length in joint space");
    a.assumptions.push_back("rigid links and ideal torque sources");
  } else {
    if (!path.empty()) a.assumptions.push_back("the tip follows the given path (" + path + "), parametrised by its arc length");
    a.assumptions.push_back("elbow configuration " + jsonv::str(to, "configuration") +
                            " throughout; rigid links and ideal torque sources");
  }
  if (!jsonv::has(lim, "acceleration_rad_s2") || lim["acceleration_rad_s2"].is_null())
    a.assumptions.push_back("no joint acceleration limit (only velocity and torque limits)");
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
                                 {"idp", "IDP"}, {"slsqp", "SLSQP"}, {"nlopt", "NLopt"}}) {
    for (size_t p = out.find(from); p != std::string::npos; p = out.find(from, p + to.size())) {
      const bool start = p == 0 || !std::isalnum(static_cast<unsigned char>(out[p - 1]));
      const bool end = p + from.size() == out.size() || !std::isalnum(static_cast<unsigned char>(out[p + from.size()]));
      if (start && end) out.replace(p, from.size(), to);
    }
  }
  if (!out.empty()) out[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(out[0])));
  return out;
}

AnswerBox answer_box(const json& results, const CasePage& page) {
  AnswerBox a;
  a.sentence = results.value("message", "");  // the study's own words, unchanged
  a.figures = page.key_figures;

  // the key picture: the locus of the motion that answers (the flight for a throw), else
  // the first strip, else the page's first figure
  std::vector<std::string> frames;
  for (const json& f : arr(results, "frames"))
    if (f.is_string()) frames.push_back(f.get<std::string>());
  const std::string study = results.value("study", "");
  std::string best;  // placement: the optimum of least energy
  if (study == "placement") {
    double e = INFINITY;
    for (const json& o : arr(obj(results, "placement"), "optima"))
      if (jsonv::num(o, "energy_J") < e) {
        e = jsonv::num(o, "energy_J");
        best = "placement_" + jsonv::str(o, "program") + "_c" + jsonv::str(o, "configuration") + "_locus.png";
      }
  }
  auto pick = [&](auto pred) {
    for (const auto& f : frames)
      if (pred(f)) return f;
    return std::string();
  };
  a.picture = pick([&](const std::string& f) { return f == best; });
  if (a.picture.empty()) a.picture = pick([](const std::string& f) { return f == "throwing_flight_locus.png"; });
  if (a.picture.empty()) a.picture = pick([](const std::string& f) { return f.ends_with("_locus.png"); });
  if (a.picture.empty()) a.picture = pick([](const std::string& f) { return f.ends_with("_strip.png"); });
  if (!a.picture.empty()) {
    a.picture_caption = a.picture.ends_with("_locus.png")
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
  int total = 0, failed = 0;
  std::vector<std::string> failures;
  for (const json& c : arr(results, "checks")) {
    ++total;
    if (!c.value("passed", false)) {
      ++failed;
      failures.push_back(check_label(jsonv::str(c, "name")));
    }
  }
  a.verdict_ok = failed == 0;
  if (total == 0)
    a.verdict = "The study ran no checks on this case.";
  else if (failed == 0)
    a.verdict = total == 1 ? "The study's check passed." : "All " + std::to_string(total) + " checks passed.";
  else
    a.verdict = std::to_string(failed) + " of " + std::to_string(total) + " checks FAILED: " +
                joined(failures, "; ") + ".";

  if (study == "placement") placement(results, a);
  else if (study == "pendulum") pendulum(results, a);
  else if (study == "throwing") throwing(results, a);
  else if (study == "time_optimal") time_optimal(results, a);
  return a;
}

}  // namespace armstudy::report
