// html -> pdf through headless chromium, one fresh profile per print
#include <fcntl.h>

#include "report/part_name.hpp"
#include <signal.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

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

// removes a folder when it goes out of scope
struct TempDir {
  fs::path path;
  ~TempDir() {
    std::error_code ec;
    if (!path.empty()) fs::remove_all(path, ec);
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
  std::string tmpl = (fs::temp_directory_path() / "armstudy-chromium-XXXXXX").string();
  if (!::mkdtemp(tmpl.data())) throw PdfError("cannot create a temporary Chromium profile");
  TempDir profile{tmpl};
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
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::error_code ec;
  fs::remove(part, ec);

  // only async-signal-safe calls between fork and exec
  const pid_t pid = ::fork();
  if (pid < 0) throw PdfError("cannot start Chromium: fork failed");
  if (pid == 0) {
    ::setpgid(0, 0);
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
    if (fd >= 0) {
      ::dup2(fd, 1);
      ::dup2(fd, 2);
    }
    const int null_in = ::open("/dev/null", O_RDONLY);
    if (null_in >= 0) ::dup2(null_in, 0);
    ::execv(argv[0], argv.data());
    ::_exit(127);
  }
  ::setpgid(pid, pid);
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  int status = 0;
  while (true) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (r < 0) throw PdfError("lost track of the Chromium process");
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(-pid, SIGKILL);  // the browser and its helper processes
      ::waitpid(pid, &status, 0);
      fs::remove(part, ec);
      throw PdfError("Chromium did not print " + html.string() + " within " +
                     std::to_string(static_cast<int>(timeout_s)) + " s");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
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
  fs::rename(part, pdf);
}

}  // namespace armstudy::report
