#include "report/scratch_dir.hpp"

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

#include "report/part_name.hpp"

namespace armstudy::report {
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

// true when the lock file exists and nobody holds it; then *fd keeps it locked
bool lock_is_free(const fs::path& lock, int* fd) {
  *fd = ::open(lock.c_str(), O_RDONLY | O_CLOEXEC);
  if (*fd < 0) return errno == ENOENT;  // a scratch folder without its lock: nobody's
  if (::flock(*fd, LOCK_EX | LOCK_NB) == 0) return true;
  ::close(*fd);
  *fd = -1;
  return false;
}

bool older_than(const fs::path& p, std::chrono::minutes age) {
  std::error_code ec;
  const auto t = fs::last_write_time(p, ec);
  return !ec && fs::file_time_type::clock::now() - t > age;
}

// moves each report waiting in <scratch>/old/ back to <dir>/<name> when <dir> has none
void restore_old(const fs::path& scratch, const fs::path& dir, std::vector<std::string>* restored) {
  std::error_code ec;
  const fs::path old = scratch / "old";
  if (!fs::is_directory(old, ec)) return;
  for (const auto& e : fs::directory_iterator(old, ec)) {
    const fs::path target = dir / e.path().filename();
    if (fs::symlink_status(target, ec).type() != fs::file_type::not_found) continue;
    if (::rename(e.path().c_str(), target.c_str()) == 0 && restored)
      restored->push_back(target.string());
  }
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

// earlier versions' `.<name>.tmp-<host>-<pid>` and `.<name>.old-<host>-<pid>`: this host's
// entries of dead processes; an `.old-` one is put back when <name> is missing
void clean_legacy(const fs::path& dir, const fs::directory_entry& e, StaleCleanup* out) {
  const std::string f = e.path().filename().string();
  char host[256] = {0};
  if (::gethostname(host, sizeof host - 1) != 0 || !host[0])
    std::snprintf(host, sizeof host, "host");
  std::string h;
  for (const char* c = host; *c; ++c)
    h += (std::isalnum(static_cast<unsigned char>(*c)) || *c == '.') ? *c : '_';
  h += "-";
  std::error_code ec;
  for (const char* kind : {".tmp-", ".old-"}) {
    const size_t at = f.rfind(kind);
    if (at == std::string::npos || at == 0 || f.compare(at + 5, h.size(), h) != 0) continue;
    const std::string pid_text = f.substr(at + 5 + h.size());
    if (pid_text.empty() || pid_text.size() > 9 ||
        pid_text.find_first_not_of("0123456789") != std::string::npos)
      continue;
    if (!process_gone(static_cast<pid_t>(std::stol(pid_text)))) continue;
    if (kind[1] == 'o') {
      const fs::path target = dir / f.substr(1, at - 1);
      if (fs::symlink_status(target, ec).type() == fs::file_type::not_found &&
          ::rename(e.path().c_str(), target.c_str()) == 0) {
        out->restored.push_back(target.string());
        continue;
      }
    }
    out->removed += fs::remove_all(e.path(), ec) > 0;
  }
}

// puts back the reports waiting in `scratch`, renames it to `<scratch>.removing` (which
// anyone may remove: a kill during the removal never leaves a folder that looks live or
// unlocked) and removes it
bool discard(const fs::path& scratch, const fs::path& dir, std::vector<std::string>* restored) {
  restore_old(scratch, dir, restored);
  std::error_code ec;
  fs::path doomed = scratch;
  doomed += kRemoving;
  if (::rename(scratch.c_str(), doomed.c_str()) != 0) doomed = scratch;
  return fs::remove_all(doomed, ec) > 0;
}

// the scratch folders, old-style leftovers and old-style part files of one folder
void clean_folder(const fs::path& dir, bool top, StaleCleanup* out) {
  std::error_code ec;
  const std::string mine = std::string(kPrefix) + process_tag();
  std::vector<fs::directory_entry> entries;
  for (const auto& e : fs::directory_iterator(dir, ec)) entries.push_back(e);
  for (const auto& e : entries) {
    const std::string f = e.path().filename().string();
    if (f.rfind(kPrefix, 0) == 0 && f.size() > kRemoving.size() &&
        f.compare(f.size() - kRemoving.size(), kRemoving.size(), kRemoving) == 0) {
      out->removed += fs::remove_all(e.path(), ec) > 0;  // its reports were put back already
    } else if (f.rfind(kPrefix, 0) == 0) {
      if (f == mine || !e.is_directory(ec)) continue;
      int fd = -1;
      if (!lock_is_free(e.path() / "lock", &fd)) continue;  // a live run's
      // no lock file: being set up right now (microseconds), or a kill came in between
      if (fd < 0 && !older_than(e.path(), std::chrono::minutes(1))) continue;
      out->removed += discard(e.path(), dir, &out->restored);
      if (fd >= 0) ::close(fd);
    } else if (top && f.size() > 1 && f[0] == '.') {
      clean_legacy(dir, e, out);
    } else if (const size_t at = f.rfind(".part-");
               at != std::string::npos && e.is_regular_file(ec)) {
      // `<file>.part-<pid>-<thread>` beside the file, as earlier versions wrote them
      const std::string rest = f.substr(at + 6);
      if (rest.find_first_not_of("0123456789-") == std::string::npos &&
          older_than(e.path(), kLegacyAge))
        out->removed += fs::remove(e.path(), ec);
    }
  }
}

void remove_own_scratch_locked() {
  Registry& r = registry();
  std::lock_guard<std::mutex> lock(r.mu);
  for (auto& [dir, s] : r.by_dir) {
    discard(s.path, dir, nullptr);
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

std::string system_error_text(const std::string& what, const fs::path& path, int err) {
  return "cannot " + what + " " + path.string() + ": " +
         std::error_code(err, std::generic_category()).message();
}

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

StaleCleanup remove_stale_scratch(const fs::path& dir) {
  StaleCleanup out;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return out;
  clean_folder(dir, true, &out);
  std::vector<fs::path> subs;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.is_directory(ec) && e.path().filename().string()[0] != '.') subs.push_back(e.path());
  for (const auto& s : subs) clean_folder(s, false, &out);
  return out;
}

fs::path part_path(const fs::path& path) {
  const size_t thread = std::hash<std::thread::id>{}(std::this_thread::get_id()) % 1000000;
  const std::string name = path.filename().string() + ".part-" + std::to_string(thread);
  const fs::path parent = path.has_parent_path() ? path.parent_path() : fs::path(".");
  if (inside_own_scratch(parent)) return parent / name;
  return scratch_dir(parent) / name;
}

void write_file_atomic(const fs::path& path, const std::string& text) {
  const fs::path part = part_path(path);
  const int fd = ::open(part.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw std::runtime_error(system_error_text("write", path, errno));
  const char* p = text.data();
  size_t left = text.size();
  int err = 0;
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      err = n < 0 ? errno : EIO;
      break;
    }
    p += n;
    left -= static_cast<size_t>(n);
  }
  if (::close(fd) != 0 && !err) err = errno;
  if (!err && ::rename(part.c_str(), path.c_str()) != 0) err = errno;
  if (err) {
    ::unlink(part.c_str());
    throw std::runtime_error(system_error_text("write", path, err));
  }
}

}  // namespace armstudy::report
