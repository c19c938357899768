// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "sys/scratch_dir.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <mutex>
#include <random>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "sys/atomic_file.hpp"
#include "sys/safe_remove.hpp"

namespace armstudy::sys {
namespace fs = std::filesystem;

namespace {

constexpr const char* kPrefix = ".armstudy-";
constexpr auto kLegacyAge = std::chrono::minutes(10);
const std::string kRemoving = ".removing";

struct Scratch {
  fs::path path;  // <dir>/.armstudy-<tag>, canonical
  int lock_fd = -1;
};

// never destroyed: atexit handlers and a signal's clean-up may run after static destructors
struct Registry {
  std::mutex mu;
  std::map<fs::path, Scratch> by_dir;  // canonical dir -> its scratch folder
  bool stopping = false;               // stop_scratch(): no new scratch folder
};
Registry& registry() {
  static Registry* r = new Registry;
  return *r;
}

fs::path canonical_dir(const fs::path& dir) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(dir, ec), ec);
  if (ec) p = fs::absolute(dir).lexically_normal();
  return p;
}

// true when the lock file of the scratch folder `name` (in `dir_fd`) exists and nobody
// holds it, or is missing; then *fd keeps it locked (-1 when missing)
bool lock_is_free(int dir_fd, const std::string& name, int* fd) {
  *fd = -1;
  const int scratch = open_folder_at(dir_fd, name);
  if (scratch < 0) return false;
  *fd = ::openat(scratch, "lock", O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  const int e = errno;
  ::close(scratch);
  if (*fd < 0) return e == ENOENT;  // a scratch folder without its lock: nobody's
  if (::flock(*fd, LOCK_EX | LOCK_NB) == 0) return true;
  ::close(*fd);
  *fd = -1;
  return false;
}

bool older_than(const struct stat& st, std::chrono::minutes age) {
  const auto t = std::chrono::system_clock::from_time_t(st.st_mtime);
  return std::chrono::system_clock::now() - t > age;
}

bool missing_at(int dir_fd, const std::string& name) {
  struct stat st {};
  return !stat_at(dir_fd, name, &st) && errno == ENOENT;
}

// moves each report waiting in <scratch>/old/ back to <dir>/<name> when <dir> has none
void restore_old(int dir_fd, const std::string& scratch, const fs::path& dir,
                 std::vector<std::string>* restored) {
  const int s = open_folder_at(dir_fd, scratch);
  if (s < 0) return;
  const int old = open_folder_at(s, "old");
  ::close(s);
  if (old < 0) return;
  for (const std::string& n : list_folder(old))
    if (missing_at(dir_fd, n) && ::renameat(old, n.c_str(), dir_fd, n.c_str()) == 0 && restored)
      restored->push_back((dir / n).string());
  ::close(old);
}

bool process_gone(pid_t pid) {
  if (::kill(pid, 0) != 0) return errno == ESRCH;
  FILE* f = std::fopen(("/proc/" + std::to_string(pid) + "/stat").c_str(), "r");
  if (!f) return false;
  char line[512] = {0};
  const bool got = std::fgets(line, sizeof line, f) != nullptr;
  std::fclose(f);
  if (!got) return false;
  const std::string s(line);
  const size_t paren = s.rfind(')');
  return paren != std::string::npos && paren + 2 < s.size() && s[paren + 2] == 'Z';
}

// earlier versions' `.<name>.tmp-<host>-<pid>` and `.<name>.old-<host>-<pid>` (a real
// file or folder, never a link): this host's entries of dead processes; an `.old-` one is
// put back when <name> is missing
void clean_legacy(int dir_fd, const fs::path& dir, const std::string& f, const struct stat& st,
                  StaleCleanup* out) {
  if (!S_ISDIR(st.st_mode) && !S_ISREG(st.st_mode)) return;
  char host[256] = {0};
  if (::gethostname(host, sizeof host - 1) != 0 || !host[0])
    std::snprintf(host, sizeof host, "host");
  std::string h;
  for (const char* c = host; *c; ++c)
    h += (std::isalnum(static_cast<unsigned char>(*c)) || *c == '.') ? *c : '_';
  h += "-";
  for (const char* kind : {".tmp-", ".old-"}) {
    const size_t at = f.rfind(kind);
    if (at == std::string::npos || at == 0 || f.compare(at + 5, h.size(), h) != 0) continue;
    const std::string pid_text = f.substr(at + 5 + h.size());
    if (pid_text.empty() || pid_text.size() > 9 ||
        pid_text.find_first_not_of("0123456789") != std::string::npos)
      continue;
    if (!process_gone(static_cast<pid_t>(std::stol(pid_text)))) continue;
    if (kind[1] == 'o') {
      const std::string target = f.substr(1, at - 1);
      if (missing_at(dir_fd, target) &&
          ::renameat(dir_fd, f.c_str(), dir_fd, target.c_str()) == 0) {
        out->restored.push_back((dir / target).string());
        continue;
      }
    }
    out->removed += remove_tree_at(dir_fd, f) > 0;
  }
}

// puts back the reports waiting in the scratch folder `name` of `dir_fd`, renames it to
// `<name>.removing` (which anyone may remove: a kill during the removal never leaves a
// folder that looks live or unlocked) and removes it, never through a link
bool discard(int dir_fd, const std::string& name, const fs::path& dir,
             std::vector<std::string>* restored) {
  restore_old(dir_fd, name, dir, restored);
  std::string doomed = name + kRemoving;
  if (::renameat(dir_fd, name.c_str(), dir_fd, doomed.c_str()) != 0) doomed = name;
  return remove_tree_at(dir_fd, doomed) > 0;
}

// `<file>.part-<pid>-<thread>`, as earlier versions wrote them beside the file
bool legacy_part(const std::string& f) {
  const size_t at = f.rfind(".part-");
  if (at == std::string::npos || at == 0) return false;
  const std::string rest = f.substr(at + 6);
  const size_t dash = rest.find('-');
  return dash != std::string::npos && dash > 0 && dash + 1 < rest.size() &&
         rest.find_first_not_of("0123456789-") == std::string::npos &&
         rest.find('-', dash + 1) == std::string::npos;
}

// a name scratch_dir() gives: .armstudy-<host>-<pid>-<8 hex digits> (a user's
// .armstudy-cache is not one)
bool scratch_name(const std::string& f) {
  if (f.rfind(kPrefix, 0) != 0) return false;
  const size_t r = f.rfind('-');
  if (r == std::string::npos || f.size() - r - 1 != 8) return false;
  for (size_t k = r + 1; k < f.size(); ++k)
    if (!std::isxdigit(static_cast<unsigned char>(f[k]))) return false;
  const size_t p = f.rfind('-', r - 1);
  if (p == std::string::npos || p + 1 == r || p < std::string(kPrefix).size()) return false;
  for (size_t k = p + 1; k < r; ++k)
    if (!std::isdigit(static_cast<unsigned char>(f[k]))) return false;
  return true;
}

// the scratch folders, old-style leftovers and old-style part files of the open folder
// `dir_fd` (`dir`): only entries armstudy names itself, each a real folder or file (a link
// of such a name is left alone), never anything through a link. In the output folder
// itself (`top`) a part file is one of a run-level file's; in a case folder any.
void clean_folder(int dir_fd, const fs::path& dir, bool top, const StaleRules& rules,
                  StaleCleanup* out) {
  const std::string mine = std::string(kPrefix) + process_tag();
  for (const std::string& f : list_folder(dir_fd)) {
    struct stat st {};
    if (!stat_at(dir_fd, f, &st)) continue;
    const bool folder = S_ISDIR(st.st_mode);
    if (f.rfind(kPrefix, 0) == 0 && f.size() > kRemoving.size() &&
        f.compare(f.size() - kRemoving.size(), kRemoving.size(), kRemoving) == 0) {
      // its reports are back
      if (folder && scratch_name(f.substr(0, f.size() - kRemoving.size())))
        out->removed += remove_tree_at(dir_fd, f) > 0;
    } else if (f.rfind(kPrefix, 0) == 0) {
      if (f == mine || !folder || !scratch_name(f)) continue;  // a user's .armstudy-cache
      int fd = -1;
      if (!lock_is_free(dir_fd, f, &fd)) continue;  // a live run's
      // no lock file, armstudy's marker: being set up right now (microseconds), or a kill
      // came in between (then it is empty); a folder with anything in it is not armstudy's
      if (fd < 0) {
        if (older_than(st, std::chrono::minutes(1)))
          out->removed += ::unlinkat(dir_fd, f.c_str(), AT_REMOVEDIR) == 0;
        continue;
      }
      out->removed += discard(dir_fd, f, dir, &out->restored);
      if (fd >= 0) ::close(fd);
    } else if (top && f.size() > 1 && f[0] == '.') {
      clean_legacy(dir_fd, dir, f, st, out);
    } else if (S_ISREG(st.st_mode) && legacy_part(f) && older_than(st, kLegacyAge)) {
      const std::string base = f.substr(0, f.rfind(".part-"));
      if (!top || rules.run_level_file(base)) out->removed += ::unlinkat(dir_fd, f.c_str(), 0) == 0;
    }
  }
}

void remove_own_scratch_locked() {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mu);
  for (auto& [dir, s] : r.by_dir) {
    const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dir_fd >= 0) {
      discard(dir_fd, s.path.filename().string(), dir, nullptr);
      ::close(dir_fd);
    }
    if (s.lock_fd >= 0) ::close(s.lock_fd);
  }
  r.by_dir.clear();
}

void remove_at_exit() {
  std::lock_guard<std::mutex> lock(swap_mutex());
  remove_own_scratch_locked();
}

// the canonical scratch folder that holds `p`, or empty
bool inside_own_scratch(const fs::path& p) {
  const fs::path c = canonical_dir(p);
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mu);
  for (const auto& [dir, s] : r.by_dir) {
    auto [a, b] = std::mismatch(s.path.begin(), s.path.end(), c.begin(), c.end());
    if (a == s.path.end()) return true;
  }
  return false;
}

}  // namespace

const std::string& process_tag() {
  static const std::string tag = [] {
    char host[256] = {0};
    if (::gethostname(host, sizeof host - 1) != 0 || !host[0])
      std::snprintf(host, sizeof host, "host");
    std::string h;
    for (const char* c = host; *c && h.size() < 64; ++c)
      h += (std::isalnum(static_cast<unsigned char>(*c)) || *c == '.') ? *c : '_';
    std::random_device rd;
    char rnd[16];
    std::snprintf(rnd, sizeof rnd, "%08x", static_cast<unsigned>(rd()));
    return h + "-" + std::to_string(::getpid()) + "-" + rnd;
  }();
  return tag;
}

std::mutex& swap_mutex() {
  static std::mutex* m = new std::mutex;
  return *m;
}

fs::path scratch_dir(const fs::path& dir) {
  const fs::path key = canonical_dir(dir);
  Registry& r = registry();
  std::unique_lock<std::mutex> lock(r.mu);
  if (r.stopping) {
    // the process is stopping on a signal, whose clean-up ends it: a folder made now would
    // outlive it, so wait for the end
    lock.unlock();
    for (;;) ::pause();
  }
  if (auto it = r.by_dir.find(key); it != r.by_dir.end()) return it->second.path;
  static std::once_flag once;
  std::call_once(once, [] { std::atexit(remove_at_exit); });
  const fs::path path = key / (kPrefix + process_tag());
  const fs::path lock_path = path / "lock";
  // a cleaner that finds the folder before its lock file is made leaves it alone for a
  // minute; one that takes the lock between open() and flock() removes the folder: then
  // the lock this process gets is on a removed file, and it starts again
  for (int attempt = 0; attempt < 4; ++attempt) {
    if (::mkdir(path.c_str(), 0777) != 0 && errno != EEXIST)
      throw std::runtime_error(system_error_text("create the temporary folder", path, errno));
    const int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd < 0) {
      const int e = errno;
      if (e == ENOENT) continue;
      throw std::runtime_error(system_error_text("create the lock file", lock_path, e));
    }
    struct stat held {
    }, named{};
    if (::flock(fd, LOCK_EX) == 0 && ::fstat(fd, &held) == 0 &&
        ::stat(lock_path.c_str(), &named) == 0 && held.st_ino == named.st_ino &&
        held.st_dev == named.st_dev) {
      r.by_dir.emplace(key, Scratch{path, fd});
      return path;
    }
    ::close(fd);
  }
  throw std::runtime_error("cannot set up the temporary folder " + path.string() +
                           ": other runs kept removing it");
}

void stop_scratch() {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mu);
  r.stopping = true;
}

void remove_own_scratch() {
  std::lock_guard<std::mutex> lock(swap_mutex());
  remove_own_scratch_locked();
}

StaleCleanup remove_stale_scratch(const fs::path& dir, const StaleRules& rules) {
  StaleCleanup out;
  // the output folder as the user named it (a link given as --out is followed: it is the
  // user's choice); below it, nothing through a link
  const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd < 0) return out;
  clean_folder(dir_fd, dir, true, rules, &out);
  for (const std::string& name : list_folder(dir_fd)) {
    if (name[0] == '.') continue;
    const int sub = open_folder_at(dir_fd, name);
    if (sub < 0) continue;  // a file, or a link (to a folder elsewhere, say): left alone
    // only folders with something armstudy names itself in them are checked further
    const auto names = list_folder(sub);
    const bool candidates = std::any_of(names.begin(), names.end(), [](const std::string& f) {
      return f.rfind(kPrefix, 0) == 0 || legacy_part(f);
    });
    if (candidates && rules.own_sub_folder(dir, name))
      clean_folder(sub, dir / name, false, rules, &out);
    ::close(sub);
  }
  ::close(dir_fd);
  return out;
}

fs::path part_path(const fs::path& path) {
  const size_t thread = std::hash<std::thread::id>{}(std::this_thread::get_id()) % 1000000;
  const std::string name = path.filename().string() + ".part-" + std::to_string(thread);
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (inside_own_scratch(parent)) return parent / name;
  return scratch_dir(parent) / name;
}

}  // namespace armstudy::sys
