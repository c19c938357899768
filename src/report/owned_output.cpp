// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "report/owned_output.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

#include <nlohmann/json.hpp>

#include "report/sweep_table.hpp"

namespace armstudy::report {
namespace fs = std::filesystem;

namespace {

// a results.json of armstudy's is far below this (docs/budgets.md); a larger file is not
// read to decide whose it is
constexpr size_t kResultsCap = size_t{64} << 20;
constexpr const char* kGeneratorMeta = "<meta name=\"generator\" content=\"armstudy\">";

enum class Kind { kMissing, kFile, kFolder, kLink, kOther };

Kind kind_of(const fs::path& p) {
  struct stat st {};
  if (::lstat(p.c_str(), &st) != 0) return errno == ENOENT ? Kind::kMissing : Kind::kOther;
  if (S_ISREG(st.st_mode)) return Kind::kFile;
  if (S_ISDIR(st.st_mode)) return Kind::kFolder;
  if (S_ISLNK(st.st_mode)) return Kind::kLink;
  return Kind::kOther;
}

// up to `cap` bytes of the regular file `p` (never through a link, never blocking on a
// FIFO); false when it is not one or cannot be read
bool read_head(const fs::path& p, size_t cap, std::string* out) {
  const int fd = ::open(p.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return false;
  struct stat st {};
  bool ok = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
  out->clear();
  char buf[1 << 16];
  while (ok && out->size() < cap) {
    const ssize_t n = ::read(fd, buf, std::min(sizeof buf, cap - out->size()));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) ok = false;
    if (n <= 0) break;
    out->append(buf, static_cast<size_t>(n));
  }
  ::close(fd);
  return ok;
}

bool starts_with_text(const fs::path& p, const std::string& mark) {
  std::string head;
  return read_head(p, mark.size(), &head) && head == mark;
}

bool html_is_ours(const fs::path& p) {
  std::string head;
  return read_head(p, 4096, &head) && head.find(kGeneratorMeta) != std::string::npos;
}

// diff's frame copies: <case>/{base,new,diff}_<frame>.png, real folders and files only
bool diff_frames_are_ours(const fs::path& dir) {
  std::error_code ec;
  for (const auto& c : fs::directory_iterator(dir, ec)) {
    if (kind_of(c.path()) != Kind::kFolder) return false;
    for (const auto& f : fs::directory_iterator(c.path(), ec)) {
      const std::string n = f.path().filename().string();
      if (kind_of(f.path()) != Kind::kFile || !n.ends_with(".png") ||
          !(n.starts_with("base_") || n.starts_with("new_") || n.starts_with("diff_")))
        return false;
    }
    if (ec) return false;
  }
  return !ec;
}

bool sweep_json_is_ours(const fs::path& p) {
  std::string text;
  if (!read_head(p, kResultsCap + 1, &text) || text.size() > kResultsCap) return false;
  const auto j = nlohmann::json::parse(text, nullptr, false);
  return has_sweep_table_keys(j);
}

// an SVG figure of armstudy's plots: cairo's header, as report/plot.cpp writes it (and
// every earlier version did)
bool svg_is_ours(const fs::path& p) {
  return starts_with_text(p,
                          "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg "
                          "xmlns=\"http://www.w3.org/2000/svg\" "
                          "xmlns:xlink=\"http://www.w3.org/1999/xlink\" ");
}

std::string what_it_is(Kind k) {
  switch (k) {
    case Kind::kFile: return "a file";
    case Kind::kFolder: return "a folder";
    case Kind::kLink: return "a symbolic link";
    default: return "a FIFO, socket or device";
  }
}

}  // namespace

std::string foreign_case_folder(const fs::path& dir, const std::string& name) {
  const Kind k = kind_of(dir);
  if (k == Kind::kMissing) return "";
  if (k != Kind::kFolder) return what_it_is(k) + ", not a case folder armstudy wrote";
  std::string text;
  const Kind results = kind_of(dir / "results.json");
  if (results == Kind::kMissing)
    return "a folder armstudy did not write (it holds no results.json)";
  if (results != Kind::kFile)
    return "a folder armstudy did not write (its results.json is not a regular file but " +
           what_it_is(results) + "; expected the regular results.json armstudy writes)";
  if (!read_head(dir / "results.json", kResultsCap + 1, &text))
    return "a folder armstudy did not write (its results.json cannot be read)";
  const auto j =
      text.size() > kResultsCap ? nlohmann::json() : nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object() || !j.contains("schema_version") || !j["schema_version"].is_number_integer() ||
      !j.contains("case") || !j["case"].is_object() || !j["case"].contains("name"))
    return "a folder armstudy did not write (its results.json is not armstudy's)";
  if (j["case"]["name"] != name)
    return "a folder armstudy did not write for this case (its results.json is of case " +
           j["case"]["name"].dump() + ")";
  return "";
}

std::vector<std::string> run_level_outputs(const std::vector<std::string>& figures) {
  std::vector<std::string> names = {"index.html", "report.css", "summary.md", "junit.xml",
                                    "sweep.csv",  "sweep.json", "sweep"};
  names.insert(names.end(), figures.begin(), figures.end());
  return names;
}

std::string foreign_run_level_output(const fs::path& out_dir, const std::string& name) {
  const fs::path p = out_dir / name;
  const Kind k = kind_of(p);
  if (k == Kind::kMissing) return "";
  if (name == "diff-frames") {
    if (k != Kind::kFolder) return what_it_is(k) + ", not the frame copies armstudy diff writes";
    return diff_frames_are_ours(p) ? ""
                                   : "a folder armstudy did not write (it holds more than "
                                     "diff's <case>/{base,new,diff}_*.png copies)";
  }
  if (name == "sweep") {
    if (k != Kind::kFolder) return what_it_is(k) + ", not the sweep report armstudy writes";
    if (kind_of(p / "index.html") == Kind::kFile && html_is_ours(p / "index.html")) return "";
    if (fs::is_empty(p)) return "";
    return "a folder armstudy did not write (no index.html of armstudy's in it)";
  }
  if (k != Kind::kFile) return what_it_is(k) + ", not a file armstudy wrote";
  bool ours = false;
  if (name == "index.html" || name == "diff.html")
    ours = html_is_ours(p);
  else if (name == "diff.md")
    ours = starts_with_text(p, "# armstudy diff: ");
  else if (name == "report.css")
    ours = starts_with_text(p, "/* armstudy report");
  else if (name == "summary.md")
    ours = starts_with_text(p, "# armstudy: ");
  else if (name == "junit.xml")
    ours = starts_with_text(
        p, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"armstudy\"");
  else if (name == "sweep.csv")
    ours = starts_with_text(p, "case,status");
  else if (name == "sweep.json")
    ours = sweep_json_is_ours(p);
  else if (name.ends_with(".svg"))
    ours = svg_is_ours(p);
  return ours ? "" : "a file armstudy did not write (it lacks the mark armstudy writes into it)";
}

std::vector<std::string> foreign_outputs(const fs::path& out_dir,
                                         const std::vector<std::string>& cases,
                                         const std::vector<std::string>& run_level) {
  std::vector<std::string> found;
  for (const std::string& name : cases)
    if (const std::string why = foreign_case_folder(out_dir / name, name); !why.empty())
      found.push_back((out_dir / name).string() + ": " + why +
                      "; expected no such entry, or the case folder of an earlier run");
  for (const std::string& name : run_level)
    if (const std::string why = foreign_run_level_output(out_dir, name); !why.empty())
      found.push_back((out_dir / name).string() + ": " + why +
                      "; expected no such entry, or armstudy's own " + name);
  return found;
}

void check_run_level_output(const fs::path& out_dir, const std::string& name) {
  if (const std::string why = foreign_run_level_output(out_dir, name); !why.empty())
    throw ForeignOutput((out_dir / name).string() + ": " + why + "; armstudy leaves it as it is");
}

}  // namespace armstudy::report
