#include "cli/diff.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "cases/case_error.hpp"
#include "cli/diff_frames.hpp"
#include "app/run_case.hpp"
#include "scene/scene_error.hpp"

namespace armstudy::app {
namespace fs = std::filesystem;
using nlohmann::json;
using report::CaseDiff;
using report::FigureDiff;

namespace {

// the fields the diff reads, with their types; "" when fine, else what is wrong
std::string shape_problem(const json& r) {
  auto type_of = [](const json& v) -> std::string {
    if (v.is_null()) return "null";
    if (v.is_string()) return "a string";
    if (v.is_number()) return "a number";
    if (v.is_boolean()) return "a boolean";
    if (v.is_array()) return "a list";
    return "an object";
  };
  if (!r.is_object()) return "the file is " + type_of(r) + "; expected an object";
  if (!r.contains("case") || !r["case"].is_object() || !r["case"].contains("name") ||
      !r["case"]["name"].is_string())
    return "'case.name' is missing or not a string; expected the case's name";
  for (const char* k : {"study", "status"})
    if (!r.contains(k) || !r[k].is_string()) return std::string("'") + k + "' is missing or not a string";
  if (r.contains("message") && !r["message"].is_string()) return "'message' is " + type_of(r["message"]) + "; expected a string";
  if (r.contains("key_figures")) {
    const json& kf = r["key_figures"];
    if (!kf.is_array()) return "'key_figures' is " + type_of(kf) + "; expected a list";
    for (size_t i = 0; i < kf.size(); ++i) {
      const std::string at = "'key_figures[" + std::to_string(i) + "]";
      if (!kf[i].is_object()) return at + "' is " + type_of(kf[i]) + "; expected an object";
      if (!kf[i].contains("name") || !kf[i]["name"].is_string()) return at + ".name' is missing or not a string";
      if (!kf[i].contains("value") || !(kf[i]["value"].is_number() || kf[i]["value"].is_null()))
        return at + ".value' is missing or not a number";
      if (kf[i].contains("unit") && !kf[i]["unit"].is_string()) return at + ".unit' is not a string";
    }
  }
  if (r.contains("checks")) {
    const json& cs = r["checks"];
    if (!cs.is_array()) return "'checks' is " + type_of(cs) + "; expected a list";
    for (size_t i = 0; i < cs.size(); ++i) {
      const std::string at = "'checks[" + std::to_string(i) + "]";
      if (!cs[i].is_object() || !cs[i].contains("name") || !cs[i]["name"].is_string())
        return at + ".name' is missing or not a string";
      if (!cs[i].contains("passed") || !cs[i]["passed"].is_boolean()) return at + ".passed' is missing or not true/false";
      for (const char* k : {"value", "tolerance"})
        if (cs[i].contains(k) && !(cs[i][k].is_number() || cs[i][k].is_null())) return at + "." + k + "' is not a number";
    }
  }
  if (r.contains("frames")) {
    if (!r["frames"].is_array()) return "'frames' is " + type_of(r["frames"]) + "; expected a list";
    for (const auto& f : r["frames"])
      if (!f.is_string()) return "'frames' holds " + type_of(f) + "; expected file names";
  }
  if (r.contains("provenance") && !r["provenance"].is_object())
    return "'provenance' is " + type_of(r["provenance"]) + "; expected an object";
  if (r.contains("case") && r["case"].contains("sweep")) {
    const json& sw = r["case"]["sweep"];
    if (!sw.is_object() || !sw.contains("point") || !sw["point"].is_object())
      return "'case.sweep.point' is missing or not an object";
    for (const auto& [k, v] : sw["point"].items())
      if (!v.is_string()) return "'case.sweep.point." + k + "' is " + type_of(v) + "; expected a string";
  }
  return "";
}

std::string case_name(const json& r) { return r["case"]["name"].get<std::string>(); }

// a key figure's value: nullopt when absent, NaN when null
struct Figure {
  std::string unit;
  double value;
};

std::vector<std::pair<std::string, Figure>> figures_of(const json& r) {
  std::vector<std::pair<std::string, Figure>> out;
  for (const auto& k : r.value("key_figures", json::array()))
    out.push_back({k["name"].get<std::string>(),
                   {k.value("unit", std::string()), k["value"].is_number() ? k["value"].get<double>() : NAN}});
  return out;
}

bool same_number(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

// moved beyond the tolerance (a figure on one side only, or finite on one side only, moved)
bool beyond(const FigureDiff& f) {
  if (f.tolerance.ignore) return false;
  if (!f.base || !f.now) return true;
  const double a = *f.base, b = *f.now;
  if (same_number(a, b)) return false;
  if (!std::isfinite(a) || !std::isfinite(b)) return true;
  return std::abs(b - a) > std::max(f.tolerance.abs, f.tolerance.rel * std::abs(a));
}

const std::vector<std::pair<std::string, std::string>>& provenance_labels() {
  static const std::vector<std::pair<std::string, std::string>> labels = {
      {"armstudy_version", "armstudy version"}, {"git_commit", "git commit"},
      {"mujoco_version", "MuJoCo"},             {"mesa_version", "Mesa"},
      {"gl_renderer", "GL renderer"},           {"gl_version", "GL version"},
      {"compiler", "compiler"},                 {"cpu_model", "CPU"}};
  return labels;
}

// provenance items of a results.json (top-level version and commit as fallbacks)
std::map<std::string, std::string> provenance_of(const json& r) {
  std::map<std::string, std::string> p;
  if (r.contains("provenance"))
    for (const auto& [k, v] : r["provenance"].items())
      if (v.is_string()) p[k] = v.get<std::string>();
  for (const char* k : {"armstudy_version", "git_commit"})
    if (!p.count(k) && r.contains(k) && r[k].is_string()) p[k] = r[k].get<std::string>();
  return p;
}

std::string label_of(const std::string& key) {
  for (const auto& [k, l] : provenance_labels())
    if (k == key) return l;
  std::string l = key;
  std::replace(l.begin(), l.end(), '_', ' ');
  return l;
}

// keys in a stable order: the known ones first, then the rest by name
std::vector<std::string> provenance_keys(const std::set<std::string>& present) {
  std::vector<std::string> keys;
  for (const auto& [k, l] : provenance_labels())
    if (present.count(k)) keys.push_back(k);
  for (const auto& k : present)
    if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
  return keys;
}

std::vector<std::string> frames_of(const json& r) {
  std::vector<std::string> out;
  for (const auto& f : r.value("frames", json::array())) out.push_back(f.get<std::string>());
  return out;
}

// a folder name safe for a case's frame copies
std::string safe_name(const std::string& s) {
  std::string o;
  for (char c : s) o += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') ? c : '_';
  return o.empty() || o[0] == '.' ? "_" + o : o;
}

CaseDiff compare_case(const CaseOutput* b, const CaseOutput* n, const DiffTolerances& tol,
                      const FrameOptions& fo) {
  CaseDiff d;
  const json& any = (n ? n : b)->results;
  d.name = case_name(any);
  d.study = any["study"].get<std::string>();
  d.presence = b && n ? CaseDiff::Presence::kBoth : (n ? CaseDiff::Presence::kAdded : CaseDiff::Presence::kRemoved);
  if (b) {
    d.base_status = b->results["status"].get<std::string>();
    d.base_passed = case_passed(b->results);
    d.base_message = b->results.value("message", std::string());
  }
  if (n) {
    d.new_status = n->results["status"].get<std::string>();
    d.new_passed = case_passed(n->results);
    d.new_message = n->results.value("message", std::string());
  }
  // key figures: the base's order, then the new run's additions
  std::vector<std::pair<std::string, Figure>> bf, nf;
  if (b) bf = figures_of(b->results);
  if (n) nf = figures_of(n->results);
  std::vector<std::string> order;
  std::map<std::string, Figure> bm, nm;
  for (const auto& [k, v] : bf) { if (!bm.count(k)) order.push_back(k); bm.emplace(k, v); }
  for (const auto& [k, v] : nf) { if (!bm.count(k) && !nm.count(k)) order.push_back(k); nm.emplace(k, v); }
  for (const auto& k : order) {
    FigureDiff f;
    f.name = k;
    if (bm.count(k)) { f.base = bm[k].value; f.unit = bm[k].unit; }
    if (nm.count(k)) { f.now = nm[k].value; if (f.unit.empty()) f.unit = nm[k].unit; }
    f.tolerance = tol.lookup(d.study, k);
    f.beyond = (b && n) ? beyond(f) : false;  // an added or removed case counts once, as itself
    d.figures.push_back(std::move(f));
  }
  if (b && n) {
    // checks whose verdict changed, and checks of one run only
    const json base_checks = b->results.value("checks", json::array());
    const json new_checks = n->results.value("checks", json::array());
    std::map<std::string, const json*> bc, nc;
    std::vector<std::string> names;
    for (const auto& c : base_checks) {
      const std::string k = c["name"].get<std::string>();
      if (!bc.count(k)) names.push_back(k);
      bc[k] = &c;
    }
    for (const auto& c : new_checks) {
      const std::string k = c["name"].get<std::string>();
      if (!bc.count(k) && !nc.count(k)) names.push_back(k);
      nc[k] = &c;
    }
    auto num = [](const json* c, const char* k) -> std::optional<double> {
      if (!c || !c->contains(k)) return std::nullopt;
      return (*c)[k].is_number() ? (*c)[k].get<double>() : NAN;
    };
    for (const auto& k : names) {
      const json* x = bc.count(k) ? bc[k] : nullptr;
      const json* y = nc.count(k) ? nc[k] : nullptr;
      report::CheckDiff c;
      c.name = k;
      if (x) c.base_passed = (*x)["passed"].get<bool>();
      if (y) c.new_passed = (*y)["passed"].get<bool>();
      if (c.base_passed == c.new_passed) continue;
      c.base_value = num(x, "value");
      c.new_value = num(y, "value");
      c.base_tolerance = num(x, "tolerance");
      c.new_tolerance = num(y, "tolerance");
      d.checks.push_back(std::move(c));
    }
    // frames: every file of either run; a run rendered without frames (--no-render) has none
    const auto fb = frames_of(b->results), fn = frames_of(n->results);
    std::vector<std::string> files = fb;
    for (const auto& f : fn)
      if (std::find(files.begin(), files.end(), f) == files.end()) files.push_back(f);
    for (const auto& f : files) {
      const bool in_b = std::find(fb.begin(), fb.end(), f) != fb.end();
      const bool in_n = std::find(fn.begin(), fn.end(), f) != fn.end();
      if (in_b && in_n) {
        d.frames.push_back(compare_frame(b->folder, n->folder, f, fo.channel_tolerance, fo.pixels_allowed,
                                         fo.frames_root, "diff-frames/" + safe_name(d.name)));
      } else {
        report::FrameDiff x;
        x.file = f;
        x.in_base = in_b;
        x.in_new = in_n;
        // a frame gone or new counts unless that run rendered no frames at all
        x.beyond = !fb.empty() && !fn.empty();
        d.frames.push_back(std::move(x));
      }
    }
    // provenance
    const auto pb = provenance_of(b->results), pn = provenance_of(n->results);
    std::set<std::string> keys;
    for (const auto& [k, v] : pb) keys.insert(k);
    for (const auto& [k, v] : pn) keys.insert(k);
    for (const auto& k : provenance_keys(keys)) {
      const std::string x = pb.count(k) ? pb.at(k) : "", y = pn.count(k) ? pn.at(k) : "";
      if (x != y) d.provenance.push_back({k, label_of(k), x.empty() ? "(none)" : x, y.empty() ? "(none)" : y});
    }
  }
  return d;
}

std::string point_text(const json& row) {
  std::string s;
  if (row.contains("parameters"))
    for (const auto& [k, v] : row["parameters"].items())
      s += (s.empty() ? "" : ", ") + k + " = " + (v.is_string() ? v.get<std::string>() : v.dump());
  return s;
}

// the sweep tables (app::sweep_json of each run) row by row by case id
void diff_sweeps(const std::vector<CaseOutput>& base, const std::vector<CaseOutput>& now,
                 report::RunDiff* out) {
  const json tb = sweep_json(base), tn = sweep_json(now);
  out->sweep_rows_base = tb["rows"].size();
  out->sweep_rows_new = tn["rows"].size();
  if (tb["rows"].empty() && tn["rows"].empty()) return;
  for (const auto* run : {&now, &base})
    for (const auto& c : *run)
      if (out->sweep_name.empty() && c.results["case"].contains("sweep"))
        out->sweep_name = c.results["case"]["sweep"].value("name", std::string("sweep"));
  std::map<std::string, const json*> rb, rn;
  for (const auto& r : tb["rows"]) rb[r["case"].get<std::string>()] = &r;
  for (const auto& r : tn["rows"]) rn[r["case"].get<std::string>()] = &r;
  std::set<std::string> names;
  for (const auto& [k, v] : rb) names.insert(k);
  for (const auto& [k, v] : rn) names.insert(k);
  std::map<std::string, const CaseDiff*> cases;
  for (const auto& c : out->cases) cases[c.name] = &c;
  auto units_of = [](const json& t, const std::string& f) {
    return t.contains("units") && t["units"].contains(f) ? t["units"][f].get<std::string>() : std::string();
  };
  for (const auto& name : names) {
    const json* x = rb.count(name) ? rb[name] : nullptr;
    const json* y = rn.count(name) ? rn[name] : nullptr;
    report::SweepRowDiff row;
    row.case_name = name;
    row.point = point_text(y ? *y : *x);
    row.base_status = x ? (*x)["status"].get<std::string>() : "";
    row.new_status = y ? (*y)["status"].get<std::string>() : "";
    row.beyond = cases.count(name) && cases[name]->beyond();
    if (!x || !y || row.base_status != row.new_status) row.score = INFINITY;
    // figures the tolerances ignore (wall-clock run times) rank nothing
    std::set<std::string> ignored;
    if (cases.count(name))
      for (const auto& f : cases[name]->figures)
        if (f.tolerance.ignore) ignored.insert(f.name);
    std::set<std::string> figs;  // a row of one run only ranks as infinite, with no figure
    if (x && y) for (const auto& [k, v] : (*x)["key_figures"].items()) figs.insert(k);
    if (x && y) for (const auto& [k, v] : (*y)["key_figures"].items()) figs.insert(k);
    double best = -1;
    for (const auto& f : figs) {
      if (ignored.count(f)) continue;
      std::optional<double> a, b;
      if (x && (*x)["key_figures"].contains(f))
        a = (*x)["key_figures"][f].is_number() ? (*x)["key_figures"][f].get<double>() : NAN;
      if (y && (*y)["key_figures"].contains(f))
        b = (*y)["key_figures"][f].is_number() ? (*y)["key_figures"][f].get<double>() : NAN;
      if (a && b && same_number(*a, *b)) continue;
      ++row.figures_changed;
      double rel = INFINITY;
      if (a && b && std::isfinite(*a) && std::isfinite(*b) && *a != 0) rel = std::abs(*b - *a) / std::abs(*a);
      if (rel > best) {
        best = rel;
        row.figure = f;
        row.unit = units_of(y && b ? tn : tb, f);
        row.base = a;
        row.now = b;
      }
    }
    if (best >= 0) row.score = std::max(row.score, best);
    if (row.figures_changed == 0 && row.score == 0 && row.base_status == row.new_status) continue;
    out->sweep.push_back(std::move(row));
  }
  std::stable_sort(out->sweep.begin(), out->sweep.end(), [](const auto& a, const auto& b) {
    if (a.beyond != b.beyond) return a.beyond;
    return a.score > b.score;
  });
}

}  // namespace

std::vector<CaseOutput> read_run(const fs::path& dir) {
  if (!fs::exists(dir)) throw DiffInputError(dir.string() + ": no such folder; expected an output folder of 'armstudy run' or 'merge'");
  if (!fs::is_directory(dir)) throw DiffInputError(dir.string() + ": not a folder; expected an output folder of 'armstudy run' or 'merge'");
  std::vector<std::string> problems;
  std::vector<CaseOutput> out = collect_outputs({dir}, &problems);
  for (const auto& c : out) {
    const std::string p = shape_problem(c.results);
    if (!p.empty()) problems.push_back((c.folder / "results.json").string() + ": " + p);
  }
  if (!problems.empty()) {
    std::string msg;
    for (const auto& p : problems) msg += (msg.empty() ? "" : "\n") + p;
    throw DiffInputError(msg);
  }
  if (out.empty())
    throw DiffInputError(dir.string() + ": no case folder with a results.json; expected an output folder of 'armstudy run' or 'merge'");
  return out;
}

report::RunDiff diff_runs(const std::vector<CaseOutput>& base, const std::vector<CaseOutput>& now,
                          const DiffTolerances& tolerances, const FrameOptions& frames) {
  report::RunDiff d;
  d.tolerances_file = tolerances.file;
  d.pixel_tolerance = frames.channel_tolerance;
  d.pixels_allowed = frames.pixels_allowed;
  d.base_cases = base.size();
  d.new_cases = now.size();
  std::map<std::string, const CaseOutput*> b, n;
  for (const auto& c : base) b[case_name(c.results)] = &c;
  for (const auto& c : now) n[case_name(c.results)] = &c;
  std::set<std::string> names;
  for (const auto& [k, v] : b) names.insert(k);
  for (const auto& [k, v] : n) names.insert(k);
  for (const auto& name : names)
    d.cases.push_back(compare_case(b.count(name) ? b[name] : nullptr, n.count(name) ? n[name] : nullptr,
                                   tolerances, frames));
  // the runs' provenance as a whole: each item's distinct values over all cases
  std::map<std::string, std::set<std::string>> pb, pn;
  for (const auto& c : base) for (const auto& [k, v] : provenance_of(c.results)) pb[k].insert(v);
  for (const auto& c : now) for (const auto& [k, v] : provenance_of(c.results)) pn[k].insert(v);
  std::set<std::string> keys;
  for (const auto& [k, v] : pb) keys.insert(k);
  for (const auto& [k, v] : pn) keys.insert(k);
  auto join = [](const std::set<std::string>& s) {
    std::string o;
    for (const auto& v : s) o += (o.empty() ? "" : "; ") + v;
    return o.empty() ? std::string("(none)") : o;
  };
  for (const auto& k : provenance_keys(keys)) {
    const std::set<std::string> x = pb.count(k) ? pb[k] : std::set<std::string>{};
    const std::set<std::string> y = pn.count(k) ? pn[k] : std::set<std::string>{};
    if (x != y) d.provenance.push_back({k, label_of(k), join(x), join(y)});
  }
  diff_sweeps(base, now, &d);
  return d;
}

int run_diff(const DiffOptions& o) {
  constexpr int kSame = 0, kMoved = 1, kBadInput = 2, kRuntime = 3;
  std::vector<CaseOutput> base, now;
  DiffTolerances tol;
  try {
    base = read_run(o.base);
    now = read_run(o.now);
    if (!o.tolerances_file.empty()) tol = load_diff_tolerances(o.tolerances_file);
  } catch (const DiffInputError& e) {
    std::fprintf(stderr, "%s\nnothing was written\n", e.what());
    return kBadInput;
  } catch (const cases::CaseErrors& e) {
    std::fprintf(stderr, "%s\nnothing was written\n", e.what());
    return kBadInput;
  }
  FrameOptions fo;
  fo.channel_tolerance = o.pixel_tolerance.value_or(tol.pixel_channel.value_or(0));
  fo.pixels_allowed = o.pixels_allowed.value_or(tol.pixels.value_or(0));
  report::RunDiff d;
  try {
    // frame copies go to a hidden sibling first; the old diff's frames go only once the new
    // ones are complete
    fs::create_directories(o.out);
    const fs::path tmp = o.out / (".diff.tmp-" + process_tag());
    fs::remove_all(tmp);
    fs::create_directories(tmp);
    fo.frames_root = tmp;
    d = diff_runs(base, now, tol, fo);
    d.base_dir = o.base;
    d.new_dir = o.now;
    fs::remove_all(o.out / "diff-frames");
    if (fs::exists(tmp / "diff-frames")) fs::rename(tmp / "diff-frames", o.out / "diff-frames");
    fs::remove_all(tmp);
    write_file_atomic(o.out / "diff.md", report::diff_markdown(d));
    report::write_diff_page(o.out, d);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "armstudy diff: cannot write the diff into %s: %s\n", o.out.c_str(), e.what());
    return kRuntime;
  }
  const size_t moved = d.beyond_count();
  std::string names;
  size_t listed = 0;
  for (const auto& c : d.cases)
    if (c.beyond() && listed++ < 10) names += "\n  " + c.name;
  if (listed > 10) names += "\n  ... and " + std::to_string(listed - 10) + " more";
  std::fprintf(stderr, "%zu case(s) in %s, %zu in %s: %s%s\ndiff: %s, %s\n", base.size(), o.base.c_str(),
               now.size(), o.now.c_str(),
               moved ? (std::to_string(moved) + " moved beyond tolerance:").c_str()
                     : "nothing moved beyond tolerance",
               names.c_str(), (o.out / "diff.html").c_str(), (o.out / "diff.md").c_str());
  return moved ? kMoved : kSame;
}

}  // namespace armstudy::app
