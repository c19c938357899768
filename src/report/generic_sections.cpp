// the parts of a page every study shares: axis labels from unit-suffixed keys, time series
// found anywhere in a results section, and a table of scalar results
#include <algorithm>
#include <sstream>
#include <map>

#include "report/number_format.hpp"
#include "report/study_sections.hpp"

namespace armstudy::report {
namespace {

using nlohmann::json;

struct UnitSuffix {
  const char* suffix;
  const char* unit;
};
// longest first: "_rad_s2" before "_rad_s" before "_s"
constexpr UnitSuffix kUnits[] = {
    {"_rad_s2", "rad/s²"}, {"_rad_s", "rad/s"}, {"_m_s2", "m/s²"}, {"_m_s", "m/s"},
    {"_deg_s", "deg/s"},   {"_Nm", "N m"},      {"_J", "J"},       {"_W", "W"},
    {"_V", "V"},           {"_A", "A"},         {"_rad", "rad"},   {"_deg", "deg"},
    {"_kg", "kg"},         {"_pct", "%"},       {"_percent", "%"}, {"_ms", "ms"},
    {"_m", "m"},           {"_s", "s"},
};

// what a plotted quantity is called, by its key stem
std::string quantity_name(const std::string& stem) {
  static const std::map<std::string, std::string> names = {
      {"q", "joint angle"},          {"qd", "joint velocity"},
      {"qdd", "joint acceleration"}, {"tau", "joint torque"},
      {"torque", "joint torque"},    {"power", "power"},
      {"theta", "angle"},            {"theta_d", "angular velocity"},
      {"voltage", "voltage"},        {"current", "current"},
      {"sd", "path speed s'"},       {"s", "path position s"},
  };
  if (auto it = names.find(stem); it != names.end()) return it->second;
  std::string out = stem;
  std::replace(out.begin(), out.end(), '_', ' ');
  return out;
}

// owner label and colour key of a json object holding a time series, if it names itself
bool owner_of(const json& j, std::string* label, std::string* colour_key) {
  if (!j.is_object()) return false;
  if (j.contains("program") && j["program"].is_string() && j.contains("configuration")) {
    const std::string prog = j["program"].get<std::string>();
    const std::string conf = jsonv::str(j, "configuration");
    *label = prog + ", configuration " + conf;
    *colour_key = prog + "/" + conf;
    if (j.contains("label") && j["label"].is_string() && !j["label"].get<std::string>().empty())
      *label = j["label"].get<std::string>() + " (" + *label + ")";
    return true;
  }
  for (const char* k : {"solver", "name", "label"})
    if (j.contains(k) && j[k].is_string()) {
      *label = j[k].get<std::string>();
      *colour_key = *label;
      return true;
    }
  return false;
}

struct Found {
  const json* obj;
  std::string label, colour_key;
  size_t n;
};

void find_series(const json& j, const std::string& label, const std::string& colour_key,
                 std::vector<Found>* out) {
  std::string l = label, c = colour_key;
  owner_of(j, &l, &c);
  if (j.is_object()) {
    if (j.contains("t_s") && j["t_s"].is_array() && j["t_s"].size() >= 2)
      out->push_back({&j, l, c, j["t_s"].size()});
    for (const auto& [k, v] : j.items())
      if (v.is_object() || (v.is_array() && !v.empty() && v[0].is_object()))
        find_series(v, l, c, out);
  } else if (j.is_array()) {
    for (const auto& e : j) find_series(e, l, c, out);
  }
}

// the columns of obj[key] as sample vectors of length n (one for a plain array)
std::vector<std::vector<double>> columns_of(const json& obj, const std::string& key, size_t n) {
  std::vector<std::vector<double>> cols;
  const json& a = obj[key];
  if (!a.is_array() || a.empty()) return cols;
  if (a.size() == n && a[0].is_number()) {
    cols.push_back(jsonv::vec(obj, key.c_str()));
  } else if (a.size() == n && a[0].is_array()) {
    for (size_t c = 0; c < a[0].size(); ++c) cols.push_back(jsonv::column(obj, key.c_str(), c, n));
  } else if (a[0].is_array() && a[0].size() == n) {
    for (size_t c = 0; c < a.size(); ++c) cols.push_back(jsonv::column(obj, key.c_str(), c, n));
  }
  return cols;
}

LineStyle column_style(size_t c) {
  return c == 0 ? LineStyle::kSolid : c == 1 ? LineStyle::kDashed : LineStyle::kDotted;
}

}  // namespace

std::string label_from_key(const std::string& key) {
  for (const auto& u : kUnits) {
    const std::string suf = u.suffix;
    if (key.size() > suf.size() && key.compare(key.size() - suf.size(), suf.size(), suf) == 0)
      return quantity_name(key.substr(0, key.size() - suf.size())) + " (" + u.unit + ")";
  }
  return quantity_name(key);
}

int time_series_figures(const json& node, const std::string& what, FigureWriter& figures,
                        Section& section, const std::vector<std::string>& skip) {
  std::vector<Found> found;
  find_series(node, "", "", &found);
  // quantities in first-seen order, then every owner that has them
  std::vector<std::string> keys;
  for (const auto& f : found)
    for (const auto& [k, v] : f.obj->items()) {
      if (k == "t_s" || !v.is_array()) continue;
      if (std::find(skip.begin(), skip.end(), k) != skip.end()) continue;
      if (std::find(keys.begin(), keys.end(), k) == keys.end() && !columns_of(*f.obj, k, f.n).empty())
        keys.push_back(k);
    }
  int added = 0;
  for (const auto& key : keys) {
    LinePlot plot;
    plot.x_label = "time (s)";
    plot.y_label = label_from_key(key);
    plot.title = plot.y_label.substr(0, plot.y_label.find(" (")) + " over time";
    std::vector<const Found*> owners;
    for (const auto& f : found)
      if (f.obj->contains(key) && !columns_of(*f.obj, key, f.n).empty()) owners.push_back(&f);
    for (size_t o = 0; o < owners.size(); ++o) {
      const Found& f = *owners[o];
      const auto t = jsonv::vec(*f.obj, "t_s");
      const auto cols = columns_of(*f.obj, key, f.n);
      for (size_t c = 0; c < cols.size(); ++c) {
        Series s;
        s.x = t;
        s.y = cols[c];
        const std::string joint = cols.size() > 1 ? "joint " + std::to_string(c + 1) : "";
        if (owners.size() == 1) {
          // one owner: colour per joint
          s.colour = colour_for(cols.size() > 1 ? "joint" + std::to_string(c + 1) : "energy");
          s.label = joint.empty() ? (f.label.empty() ? plot.title : f.label) : joint;
        } else {
          s.colour = colour_for(f.colour_key.empty() ? f.label : f.colour_key);
          s.style = column_style(c);
          s.label = f.label.empty() ? "series " + std::to_string(o + 1) : f.label;
          if (!joint.empty()) s.label += ", " + joint;
        }
        plot.series.push_back(std::move(s));
      }
    }
    if (plot.series.empty()) continue;
    std::string caption = plot.title + (what.empty() ? "" : " — " + what) + ".";
    if (owners.size() > 1)
      caption += " One colour per series (the same in every plot); solid lines are joint 1, "
                 "dashed joint 2, dotted joint 3 and beyond.";
    section.figure(figures.line(key, plot, caption));
    ++added;
  }
  return added;
}

namespace {
void flatten_json(const json& j, const std::string& path, Table* t) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) flatten_json(v, path.empty() ? k : path + "." + k, t);
  } else if (j.is_array()) {
    std::string v = "[";
    for (size_t i = 0; i < j.size(); ++i) {
      if (j[i].is_string()) return;  // sentences: shown elsewhere
      if (!j[i].is_primitive()) return;
      v += (i ? ", " : "") + (j[i].is_number() ? format_sig(j[i].get<double>(), 6) : j[i].dump());
    }
    t->rows.push_back({path, v + "]"});
  } else if (!j.is_null()) {
    t->rows.push_back({path, j.is_number() ? format_sig(j.get<double>(), 6)
                                           : j.is_string() ? j.get<std::string>() : j.dump()});
  }
}
}  // namespace

Table json_table(const json& obj, std::string caption) {
  Table t;
  t.caption = std::move(caption);
  t.header = {"quantity", "value"};
  flatten_json(obj, "", &t);
  // the dotted key paths in words: "tray.circle_offset_m" -> "tray, circle offset (m)"
  for (auto& row : t.rows) {
    if (row.empty()) continue;
    std::string words, part;
    std::stringstream in(row[0]);
    while (std::getline(in, part, '.')) words += (words.empty() ? "" : ", ") + label_from_key(part);
    row[0] = words;
  }
  return t;
}

LinePlot owners_plot(const std::string& title, const std::string& y_label,
                     const std::vector<Owner>& owners, const std::vector<std::string>& keys,
                     const std::vector<std::string>& key_labels) {
  LinePlot plot;
  plot.title = title;
  plot.x_label = "time (s)";
  plot.y_label = y_label;
  for (const Owner& o : owners) {
    if (!o.series || !jsonv::has(*o.series, "t_s")) continue;
    const auto t = jsonv::vec(*o.series, "t_s");
    size_t curve = 0;
    for (const auto& key : keys) {
      if (!o.series->contains(key)) continue;
      for (const auto& col : columns_of(*o.series, key, t.size())) {
        Series s;
        s.x = t;
        s.y = col;
        s.colour = colour_for(o.colour_key.empty() ? o.label : o.colour_key);
        s.style = column_style(curve);
        const std::string what = curve < key_labels.size() ? key_labels[curve] : label_from_key(key);
        s.label = owners.size() > 1 ? o.label + ", " + what : what;
        if (owners.size() == 1 && keys.size() + key_labels.size() > 2) {
          // a single owner: colour per curve reads better than style alone
          s.colour = colour_for("joint" + std::to_string(curve + 1));
        }
        plot.series.push_back(std::move(s));
        ++curve;
      }
    }
  }
  return plot;
}

void generic_sections(const json& section, FigureWriter& figures, CasePage& page) {
  Section s;
  s.id = "results";
  s.heading = "Results";
  Table t;
  t.header = {"quantity", "value"};
  if (section.is_object())
    for (const auto& [k, v] : section.items())
      if (v.is_primitive() && !v.is_null()) t.rows.push_back({label_from_key(k), jsonv::str(section, k.c_str())});
  if (!t.rows.empty()) s.table(std::move(t));
  time_series_figures(section, "", figures, s);
  if (s.blocks.empty()) s.paragraph("The study wrote no results for this case.");
  page.sections.push_back(std::move(s));
}

}  // namespace armstudy::report
