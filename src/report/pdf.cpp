// html -> pdf through headless chromium, one fresh profile per print
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/file.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "report/part_name.hpp"

#include "report/case_report.hpp"

namespace armstudy::report {
namespace fs = std::filesystem;

namespace {

bool is_executable(const fs::path& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(p.c_str(), X_OK) == 0;
}

// file:// url of an absolute path, percent-encoding all but unreserved characters and '/'
std::string file_url(const fs::path& p) {
  static const char* hex = "0123456789ABCDEF";
  std::string url = "file://";
  for (unsigned char c : fs::absolute(p).lexically_normal().string()) {
    if (std::isalnum(c) || c == '/' || c == '-' || c == '_' || c == '.' || c == '~') {
      url += static_cast<char>(c);
    } else {
      url += '%';
      url += hex[c >> 4];
      url += hex[c & 15];
    }
  }
  return url;
}

std::string tail_of(const fs::path& log, size_t max_chars) {
  std::ifstream in(log, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  if (s.size() > max_chars) s = "..." + s.substr(s.size() - max_chars);
  return s;
}

constexpr const char* kProfilePrefix = "armstudy-chromium-";
constexpr const char* kProfileLock = "armstudy.lock";

// the browsers printing now (process group -> profile folder), for a signal's clean-up
struct Live {
  std::mutex mu;
  std::set<pid_t> groups;
  std::map<std::string, int> profiles;  // profile folder -> its locked lock file
};
Live& live() {
  static Live* l = new Live;  // never destroyed: used by the clean-up of a signal
  return *l;
}

// a fresh profile folder under the system's temporary folder, holding a lock file this
// process keeps locked while it prints: remove_stale_profiles() leaves live ones alone
struct Profile {
  fs::path path;
  Profile() {
    std::string tmpl = (fs::temp_directory_path() / (std::string(kProfilePrefix) + "XXXXXX")).string();
    if (!::mkdtemp(tmpl.data()))
      throw PdfError(std::string("cannot create a temporary Chromium profile in ") +
                     fs::temp_directory_path().string() + ": " + std::strerror(errno));
    path = tmpl;
    const int fd = ::open((path / kProfileLock).c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600);
    if (fd >= 0) ::flock(fd, LOCK_EX | LOCK_NB);
    std::lock_guard<std::mutex> lock(live().mu);
    live().profiles[path.string()] = fd;
  }
  Profile(const Profile&) = delete;
  Profile& operator=(const Profile&) = delete;
  ~Profile() {
    std::error_code ec;
    fs::remove_all(path, ec);
    std::lock_guard<std::mutex> lock(live().mu);
    if (auto it = live().profiles.find(path.string()); it != live().profiles.end()) {
      if (it->second >= 0) ::close(it->second);
      live().profiles.erase(it);
    }
  }
};

// the browser's process group, killed (and the browser reaped) when this goes out of
// scope: on success, on a timeout and on an exception alike
struct BrowserGroup {
  pid_t pid = -1;
  bool reaped = false;
  explicit BrowserGroup(pid_t p) : pid(p) {
    std::lock_guard<std::mutex> lock(live().mu);
    live().groups.insert(pid);
  }
  BrowserGroup(const BrowserGroup&) = delete;
  BrowserGroup& operator=(const BrowserGroup&) = delete;
  ~BrowserGroup() {
    ::kill(-pid, SIGKILL);  // the browser and any helper process left in its group
    if (!reaped) {
      int status = 0;
      ::waitpid(pid, &status, 0);
    }
    std::lock_guard<std::mutex> lock(live().mu);
    live().groups.erase(pid);
  }
};

}  // namespace

std::string find_chromium() {
  if (const char* env = std::getenv("ARMSTUDY_CHROMIUM"); env && *env)
    return is_executable(env) ? env : "";
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/local/bin:/usr/bin:/bin");
  std::string dir;
  std::vector<std::string> entries;
  while (std::getline(dirs, dir, ':')) entries.push_back(dir.empty() ? "." : dir);
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"})
    for (const auto& d : entries)
      if (is_executable(fs::path(d) / name)) return (fs::path(d) / name).string();
  return "";
}

void print_pdf(const fs::path& html, const fs::path& pdf, double timeout_s) {
  const std::string chromium = find_chromium();
  if (chromium.empty())
    throw PdfError(
        "--pdf needs headless Chromium, and none was found (looked for $ARMSTUDY_CHROMIUM, then "
        "chromium, chromium-browser and google-chrome on PATH); install it with "
        "'apt-get install chromium' or set ARMSTUDY_CHROMIUM to the browser's path");
  if (!fs::exists(html)) throw PdfError("cannot print " + html.string() + ": no such file");

  // a fresh profile: no state shared between prints or with a user's browser
  Profile profile;
  const fs::path log = profile.path / "chromium.log";
  const fs::path part = part_path(pdf);

  std::vector<std::string> args = {chromium,
                                   "--headless",
                                   "--no-sandbox",
                                   "--disable-gpu",
                                   "--disable-quic",
                                   "--no-first-run",
                                   "--disable-background-networking",
                                   "--disable-component-update",
                                   "--disable-sync",
                                   "--disable-extensions",
                                   "--user-data-dir=" + profile.path.string(),
                                   "--no-pdf-header-footer",
                                   "--print-to-pdf=" + part.string(),
                                   file_url(html)};
  // the browser's own temporary files (org.chromium.Chromium.*) go inside the profile
  // too, so that removing the profile removes everything a killed browser left
  const fs::path browser_tmp = profile.path / "tmp";
  fs::create_directories(browser_tmp);
  std::vector<std::string> env_text = {"TMPDIR=" + browser_tmp.string()};
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "TMPDIR=", 7) != 0) env_text.emplace_back(*e);
  std::vector<char*> envp;
  for (auto& e : env_text) envp.push_back(e.data());
  envp.push_back(nullptr);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::error_code ec;
  fs::remove(part, ec);

  // only async-signal-safe calls between fork and exec
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) throw PdfError("cannot start Chromium: fork failed");
  if (pid == 0) {
    ::setpgid(0, 0);
    // dies with armstudy, even when armstudy is killed with SIGKILL
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    // armstudy blocks the termination signals in every thread (its signal thread waits
    // for them); the browser gets the default behaviour back
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
    }
    const int null_in = ::open("/dev/null", O_RDONLY);
    if (null_in >= 0) ::dup2(null_in, 0);
    ::execve(argv[0], argv.data(), envp.data());
    ::_exit(127);
  }
  ::setpgid(pid, pid);
  BrowserGroup group(pid);
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  int status = 0;
  while (true) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (r < 0) {
      group.reaped = true;
      fs::remove(part, ec);
      throw PdfError("lost track of the Chromium process");
    }
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(-pid, SIGKILL);  // the browser and its helper processes
      ::waitpid(pid, &status, 0);
      group.reaped = true;
      fs::remove(part, ec);
      throw PdfError("Chromium did not print " + html.string() + " within " +
                     std::to_string(static_cast<int>(timeout_s)) + " s");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  group.reaped = true;
  // helper processes of the browser's group that outlived it
  ::kill(-pid, SIGKILL);
  const bool exited_ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  std::string head;
  {
    std::ifstream in(part, std::ios::binary);
    char buf[5] = {};
    in.read(buf, 4);
    head.assign(buf, static_cast<size_t>(in.gcount()));
  }
  if (!exited_ok || head != "%PDF") {
    fs::remove(part, ec);
    throw PdfError("Chromium did not print " + html.string() +
                   (WIFEXITED(status) ? " (exit " + std::to_string(WEXITSTATUS(status)) + ")"
                                      : " (killed by a signal)") +
                   ": " + tail_of(log, 600));
  }
  if (::rename(part.c_str(), pdf.c_str()) != 0) {
    const int e = errno;
    fs::remove(part, ec);
    throw PdfError(system_error_text("write", pdf, e));
  }
}

void kill_browsers() {
  std::lock_guard<std::mutex> lock(live().mu);
  for (const pid_t pid : live().groups) ::kill(-pid, SIGKILL);
  // SIGKILL takes effect on the next return to user space: give it a moment before
  // removing what the browsers were writing
  if (!live().groups.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  std::error_code ec;
  for (const auto& [path, fd] : live().profiles) fs::remove_all(path, ec);
}

size_t remove_stale_profiles() {
  std::error_code ec;
  size_t removed = 0;
  const fs::path tmp = fs::temp_directory_path(ec);
  if (ec) return 0;
  for (const auto& e : fs::directory_iterator(tmp, ec)) {
    const std::string f = e.path().filename().string();
    if (f.rfind(kProfilePrefix, 0) != 0 || !e.is_directory(ec)) continue;
    const int fd = ::open((e.path() / kProfileLock).c_str(), O_RDONLY | O_CLOEXEC);
    bool stale = false;
    if (fd >= 0) {
      stale = ::flock(fd, LOCK_EX | LOCK_NB) == 0;  // nobody prints with it
    } else {
      // no lock file: an earlier version's profile, or one being made right now
      const auto t = fs::last_write_time(e.path(), ec);
      stale = !ec && fs::file_time_type::clock::now() - t > std::chrono::minutes(10);
    }
    if (stale) removed += fs::remove_all(e.path(), ec) > 0;
    if (fd >= 0) ::close(fd);
  }
  return removed;
}

}  // namespace armstudy::report
