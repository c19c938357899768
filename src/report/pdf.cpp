// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// html -> pdf through headless chromium over the DevTools protocol: one fresh profile per
// browser; one browser per page (print_pdf) or one for all pages of a run (print_pdfs). Every
// page is printed with scripts off and no file read outside the page's own folder.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/file.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "report/case_report.hpp"
#include "sys/atomic_file.hpp"
#include "sys/process.hpp"
#include "sys/safe_remove.hpp"

namespace armstudy::report {
namespace fs = std::filesystem;

namespace {

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

// the temporary folder: TMPDIR when it names a folder, otherwise /tmp (and a TMPDIR that
// names no folder is said once, rather than failing every print)
fs::path temp_folder() {
  static const fs::path dir = [] {
    const char* env = std::getenv("TMPDIR");
    if (!env || !*env) return fs::path("/tmp");
    std::error_code ec;
    if (fs::is_directory(env, ec)) return fs::path(env);
    std::fprintf(stderr,
                 "armstudy: TMPDIR is '%s', which is not a folder; Chromium's temporary "
                 "profiles go to /tmp\n",
                 env);
    return fs::path("/tmp");
  }();
  return dir;
}

// a fresh profile folder under the system's temporary folder, holding a lock file this
// process keeps locked while it prints: remove_stale_profiles() leaves live ones alone
struct Profile {
  fs::path path;
  Profile() {
    std::string tmpl = (temp_folder() / (std::string(kProfilePrefix) + "XXXXXX")).string();
    if (!::mkdtemp(tmpl.data()))
      throw PdfError(std::string("cannot create a temporary Chromium profile in ") +
                     temp_folder().string() + ": " + std::strerror(errno));
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

namespace {
std::atomic<bool> g_stopping{false};
bool stopping() { return g_stopping.load(); }
}  // namespace

std::string find_chromium() {
  if (const char* env = std::getenv("ARMSTUDY_CHROMIUM"); env && *env)
    return sys::is_executable(env) ? env : "";
  // chromium-headless-shell first: Chromium's headless mode built on its own (Debian's
  // package of that name), which prints the same pages as the full browser and starts with
  // about a third of its CPU (an empty page: 1.3 against 3.7 CPU-s)
  return sys::find_on_path(
      {"chromium-headless-shell", "chromium", "chromium-browser", "google-chrome"});
}

std::string missing_chromium_text() {
  return "--pdf needs headless Chromium, and none was found (looked for $ARMSTUDY_CHROMIUM, "
         "then chromium-headless-shell, chromium, chromium-browser and google-chrome on PATH); "
         "install it with 'apt-get install chromium-headless-shell' (or chromium) or set "
         "ARMSTUDY_CHROMIUM to the browser's path";
}

namespace {
std::string chromium_or_throw() {
  const std::string chromium = find_chromium();
  if (chromium.empty()) throw PdfError(missing_chromium_text());
  return chromium;
}
}  // namespace

namespace {

std::string base64_decode(const std::string& in) {
  static const auto table = [] {
    std::array<int, 256> t{};
    t.fill(-1);
    const char* a = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (int i = 0; i < 64; ++i) t[static_cast<unsigned char>(a[i])] = i;
    return t;
  }();
  std::string out;
  out.reserve(in.size() / 4 * 3);
  unsigned acc = 0;
  int bits = 0;
  for (unsigned char c : in) {
    const int v = table[c];
    if (v < 0) continue;  // '=' padding, line breaks
    acc = (acc << 6) | static_cast<unsigned>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out += static_cast<char>((acc >> bits) & 0xFF);
    }
  }
  return out;
}

// One headless Chromium driven over --remote-debugging-pipe: it reads DevTools messages
// (JSON, each ended by '\0') on fd 3 and writes its answers and events on fd 4; both are
// one end of a socket pair here (a socket, so that a browser that died is an error, not
// SIGPIPE). Killed with its process group when this goes out of scope.
class PipeBrowser {
 public:
  explicit PipeBrowser(const std::string& chromium) {
    if (stopping()) throw PdfError("stopped by a signal");
    const fs::path log = profile_.path / "chromium.log";
    sys::SpawnOptions o;
    o.argv = {chromium,
              "--headless",
              "--no-sandbox",
              "--disable-gpu",
              "--disable-quic",
              "--no-first-run",
              "--disable-background-networking",
              "--disable-component-update",
              "--disable-sync",
              "--disable-extensions",
              "--user-data-dir=" + profile_.path.string(),
              "--remote-debugging-pipe",
              "about:blank"};
    const fs::path browser_tmp = profile_.path / "tmp";
    fs::create_directories(browser_tmp);
    o.env = {"TMPDIR=" + browser_tmp.string()};
    for (std::string& e : sys::current_environment())
      if (e.rfind("TMPDIR=", 0) != 0) o.env.push_back(std::move(e));
    int sv[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0)
      throw PdfError(std::string("cannot start Chromium: socketpair: ") + std::strerror(errno));
    // its log as standard output and error, no input, and the browser's end of the socket
    // as fd 3 and fd 4; its own process group (killed whole) and dead with this thread
    o.files = {{log, O_WRONLY | O_CREAT | O_TRUNC, 0600, {1, 2}}, {"/dev/null", O_RDONLY, 0, {0}}};
    o.fds = {{sv[1], 3}, {sv[1], 4}};
    o.default_signals = {SIGPIPE};  // armstudy ignores it
    o.own_group = true;
    o.death_signal = SIGKILL;
    int error = 0;
    const pid_t pid = sys::spawn(o, &error);
    if (pid < 0) {
      ::close(sv[0]);
      ::close(sv[1]);
      throw PdfError("cannot start Chromium: fork failed");
    }
    ::close(sv[1]);
    fd_ = sv[0];
    group_.emplace(pid);
  }
  ~PipeBrowser() {
    if (fd_ >= 0) {
      // a polite close first (the browser flushes and exits), then its group is killed
      try {
        send("Browser.close", nlohmann::json::object());
      } catch (const PdfError&) {
        // gone already
      }
      const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(3);
      int status = 0;
      while (std::chrono::steady_clock::now() < until) {
        if (::waitpid(group_->pid, &status, WNOHANG) == group_->pid) {
          group_->reaped = true;
          break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      ::close(fd_);
    }
  }
  PipeBrowser(const PipeBrowser&) = delete;
  PipeBrowser& operator=(const PipeBrowser&) = delete;

  /// Sends a command (to a page's session when `session` is not empty); returns its id.
  int send(const std::string& method, const nlohmann::json& params,
           const std::string& session = "") {
    nlohmann::json m = {{"id", ++next_id_}, {"method", method}, {"params", params}};
    if (!session.empty()) m["sessionId"] = session;
    std::string text = m.dump();
    text += '\0';
    for (size_t at = 0; at < text.size();) {
      const ssize_t n = ::send(fd_, text.data() + at, text.size() - at, MSG_NOSIGNAL);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0)
        throw PdfError("lost the connection to Chromium (" + std::string(std::strerror(errno)) +
                       ")");
      at += static_cast<size_t>(n);
    }
    return next_id_;
  }

  /// The next message, waiting at most `wait_ms`; nullopt when none came in time.
  /// @throws PdfError when the browser closed its end (it exited or died).
  std::optional<nlohmann::json> receive(int wait_ms) {
    while (true) {
      const size_t end = in_.find('\0', scanned_);
      if (end != std::string::npos) {
        nlohmann::json m = nlohmann::json::parse(in_.begin(), in_.begin() + static_cast<long>(end),
                                                 nullptr, false);
        in_.erase(0, end + 1);
        scanned_ = 0;
        if (m.is_discarded()) throw PdfError("Chromium sent a message that is not JSON");
        return m;
      }
      scanned_ = in_.size();
      pollfd p{fd_, POLLIN, 0};
      const int r = ::poll(&p, 1, wait_ms);
      if (r < 0 && errno == EINTR) continue;
      if (r <= 0) return std::nullopt;
      char buf[1 << 16];
      const ssize_t n = ::read(fd_, buf, sizeof buf);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0)
        throw PdfError("Chromium closed the DevTools pipe: " +
                       tail_of(profile_.path / "chromium.log", 400));
      in_.append(buf, static_cast<size_t>(n));
      wait_ms = 0;  // the rest of a message that has begun is read at once
    }
  }

 private:
  Profile profile_;  // first: removed after the browser is gone
  std::optional<BrowserGroup> group_;
  int fd_ = -1;
  int next_id_ = 0;
  std::string in_;
  size_t scanned_ = 0;
};

// one tab printing one page: create a target, attach, enable page events, navigate, wait
// for the load event, print, close
// for the page's folder `folder`: scripts off (Emulation), every request paused (Fetch) and
// let through only for a file inside the folder, navigate, wait for the load event, print,
// close
struct Tab {
  enum Step { kIdle, kCreate, kAttach, kEnable, kNoScript, kConfine, kNavigate, kPrint, kClose };
  Step step = kIdle;
  int job = -1;
  int pending = -1;  // id of the command waiting for its answer
  bool navigated = false, loaded = false;
  std::string target, session;
  fs::path folder;  // canonical: the only folder the page may read from
  std::chrono::steady_clock::time_point deadline;
};

// the file behind a file:// URL (percent-decoded, without query or fragment); "" for any
// other URL
std::string file_of_url(const std::string& url) {
  if (url.rfind("file://", 0) != 0) return "";
  std::string path;
  for (size_t i = 7; i < url.size() && url[i] != '?' && url[i] != '#'; ++i) {
    if (url[i] == '%' && i + 2 < url.size() &&
        std::isxdigit(static_cast<unsigned char>(url[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(url[i + 2]))) {
      path += static_cast<char>(std::stoi(url.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      path += url[i];
    }
  }
  return path;
}

// true when `url` names a file inside `folder` (links resolved: a link out of it is outside)
bool inside_folder(const std::string& url, const fs::path& folder) {
  const std::string file = file_of_url(url);
  if (file.empty() || file[0] != '/') return false;
  std::error_code ec;
  const fs::path real = fs::weakly_canonical(fs::path(file), ec);
  if (ec) return false;
  auto [a, b] = std::mismatch(folder.begin(), folder.end(), real.begin(), real.end());
  return a == folder.end() && b != real.end();
}

// writes a printed page through its temporary sibling; "" or why not
std::string write_printed(const std::string& bytes, const fs::path& pdf) {
  if (bytes.compare(0, 4, "%PDF") != 0) return "Chromium printed something that is not a PDF";
  const fs::path part = sys::part_path(pdf);
  {
    std::ofstream out(part, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) {
      const int e = errno;
      std::error_code ec;
      fs::remove(part, ec);
      return sys::system_error_text("write", pdf, e);
    }
  }
  if (::rename(part.c_str(), pdf.c_str()) != 0) {
    const int e = errno;
    std::error_code ec;
    fs::remove(part, ec);
    return sys::system_error_text("write", pdf, e);
  }
  return "";
}

// the pages to print, given all at once (print_pdfs) or as the cases finish (PdfPrinter)
struct PrintQueue {
  std::mutex mu;
  std::condition_variable cv;
  std::vector<PdfJob> jobs;
  std::vector<std::function<void(const std::string&)>> on_done;  // per job, may be empty
  std::vector<std::string> errors;
  std::vector<char> done;  // printed, or failed on its own (errors)
  size_t next = 0;         // the first job no browser has taken
  bool closed = false;     // no more jobs will come

  size_t add(PdfJob job, std::function<void(const std::string&)> f) {
    std::lock_guard<std::mutex> lock(mu);
    jobs.push_back(std::move(job));
    on_done.push_back(std::move(f));
    errors.emplace_back();
    done.push_back(0);
    cv.notify_all();
    return jobs.size() - 1;
  }
  void finish(size_t i, const std::string& error) {
    std::function<void(const std::string&)> f;
    {
      std::lock_guard<std::mutex> lock(mu);
      errors[i] = error;
      done[i] = 1;
      f = on_done[i];
      cv.notify_all();
    }
    if (f) f(error);
  }
  // the next job to start (index), or nullopt when none is waiting now
  std::optional<size_t> take() {
    std::lock_guard<std::mutex> lock(mu);
    if (next < jobs.size()) return next++;
    return std::nullopt;
  }
  bool drained() {
    std::lock_guard<std::mutex> lock(mu);
    return closed && next == jobs.size();
  }
};

// one browser printing the queue's pages, up to `tabs.size()` at a time: each tab steps
// through its page's commands (Tab::Step) as the browser answers
struct TabPrinter {
  using clock = std::chrono::steady_clock;
  PipeBrowser& browser;
  PrintQueue& q;
  std::vector<Tab> tabs;
  clock::duration limit;

  PdfJob job_of(const Tab& t) {
    std::lock_guard<std::mutex> lock(q.mu);
    return q.jobs[static_cast<size_t>(t.job)];
  }
  void fail(Tab& t, const std::string& why) {
    const size_t j = static_cast<size_t>(t.job);
    if (!t.target.empty()) browser.send("Target.closeTarget", {{"targetId", t.target}});
    t = Tab{};
    q.finish(j, why);
  }
  void start(Tab& t) {
    while (t.step == Tab::kIdle) {
      const std::optional<size_t> j = q.take();
      if (!j) return;
      const PdfJob job = [&] {
        std::lock_guard<std::mutex> lock(q.mu);
        return q.jobs[*j];
      }();
      if (!fs::exists(job.html)) {
        q.finish(*j, "cannot print " + job.html.string() + ": no such file");
        continue;
      }
      t = Tab{};
      t.job = static_cast<int>(*j);
      std::error_code ec;
      t.folder = fs::weakly_canonical(fs::absolute(job.html).parent_path(), ec);
      t.deadline = clock::now() + limit;
      t.step = Tab::kCreate;
      t.pending = browser.send("Target.createTarget", {{"url", "about:blank"}});
    }
  }
  void print(Tab& t) {
    t.step = Tab::kPrint;
    // the options of headless Chromium's --print-to-pdf with --no-pdf-header-footer
    t.pending = browser.send("Page.printToPDF",
                             {{"displayHeaderFooter", false},
                              {"printBackground", true},
                              {"preferCSSPageSize", true},
                              {"transferMode", "ReturnAsBase64"}},
                             t.session);
  }
  // a page reads only files of its own folder: anything else fails as if denied
  void on_request(const nlohmann::json& m) {
    const nlohmann::json& p = m["params"];
    const std::string id = p.value("requestId", "");
    bool allowed = false;
    for (const Tab& t : tabs)
      if (t.step != Tab::kIdle && t.session == m["sessionId"])
        allowed = p.contains("request") && p["request"].is_object() &&
                  inside_folder(p["request"].value("url", ""), t.folder);
    if (allowed)
      browser.send("Fetch.continueRequest", {{"requestId", id}}, m["sessionId"]);
    else
      browser.send("Fetch.failRequest", {{"requestId", id}, {"errorReason", "AccessDenied"}},
                   m["sessionId"]);
  }
  // the answer `m` to tab t's pending command: the tab's next step (over 60 lines: one case
  // per step of the protocol, in their order)
  void on_answer(Tab& t, const nlohmann::json& m) {
    const PdfJob job = job_of(t);
    if (m.contains("error")) {
      fail(t, "Chromium could not print " + job.html.string() + ": " +
                  m["error"].value("message", m["error"].dump()));
      return;
    }
    const nlohmann::json& r = m.contains("result") ? m["result"] : nlohmann::json::object();
    switch (t.step) {
      case Tab::kCreate:
        t.target = r.value("targetId", "");
        t.step = Tab::kAttach;
        t.pending =
            browser.send("Target.attachToTarget", {{"targetId", t.target}, {"flatten", true}});
        break;
      case Tab::kAttach:
        t.session = r.value("sessionId", "");
        t.step = Tab::kEnable;
        t.pending = browser.send("Page.enable", nlohmann::json::object(), t.session);
        break;
      case Tab::kEnable:
        t.step = Tab::kNoScript;
        t.pending =
            browser.send("Emulation.setScriptExecutionDisabled", {{"value", true}}, t.session);
        break;
      case Tab::kNoScript:
        t.step = Tab::kConfine;
        t.pending =
            browser.send("Fetch.enable",
                         {{"patterns", nlohmann::json::array({{{"urlPattern", "*"}}})}}, t.session);
        break;
      case Tab::kConfine:
        t.step = Tab::kNavigate;
        t.pending = browser.send("Page.navigate", {{"url", file_url(job.html)}}, t.session);
        break;
      case Tab::kNavigate:
        if (r.contains("errorText") && r["errorText"].is_string() &&
            !r["errorText"].get<std::string>().empty()) {
          fail(t, "Chromium could not open " + job.html.string() + ": " +
                      r["errorText"].get<std::string>());
          break;
        }
        t.navigated = true;
        t.pending = -1;
        if (t.loaded) print(t);
        break;
      case Tab::kPrint: {
        const std::string why = write_printed(base64_decode(r.value("data", "")), job.pdf);
        if (!why.empty()) {
          fail(t, why);
        } else {
          const size_t j = static_cast<size_t>(t.job);
          browser.send("Target.closeTarget", {{"targetId", t.target}});
          t = Tab{};
          q.finish(j, "");
        }
        break;
      }
      default: break;
    }
  }
  // a message of the browser: an event (a paused request, a page loaded) or an answer
  void on_message(const nlohmann::json& m) {
    if (m.contains("method")) {
      if (m["method"] == "Fetch.requestPaused" && m.contains("sessionId")) {
        on_request(m);
        return;
      }
      if (m["method"] == "Page.loadEventFired" && m.contains("sessionId"))
        for (Tab& t : tabs)
          if (t.step == Tab::kNavigate && t.session == m["sessionId"]) {
            t.loaded = true;
            if (t.navigated) print(t);
          }
      return;
    }
    if (!m.contains("id")) return;
    Tab* tab = nullptr;
    for (Tab& t : tabs)
      if (t.step != Tab::kIdle && t.pending == m["id"]) tab = &t;
    if (!tab) return;  // the answer to a close, or to a page given up
    on_answer(*tab, m);
  }
};

// prints the queue's pages through one browser, as they come, until the queue is closed
// and drained; every page printed or failed on its own is finished in the queue; throws
// PdfError when the browser fails (the pages it took and did not finish are left undone)
void print_through_one_browser(const std::string& chromium, PrintQueue& q, int parallel,
                               double timeout_s) {
  using clock = std::chrono::steady_clock;
  PipeBrowser browser(chromium);
  TabPrinter tp{
      browser, q, std::vector<Tab>(static_cast<size_t>(std::clamp(parallel, 1, 8))),
      std::chrono::duration_cast<clock::duration>(std::chrono::duration<double>(timeout_s))};
  const auto limit = tp.limit;
  auto last_message = clock::now();
  while (true) {
    if (stopping()) throw PdfError("stopped by a signal");
    bool busy = false;
    for (Tab& t : tp.tabs) {
      if (t.step == Tab::kIdle) tp.start(t);
      busy |= t.step != Tab::kIdle;
    }
    if (!busy && q.drained()) return;
    const std::optional<nlohmann::json> got = browser.receive(50);
    const auto now = clock::now();
    for (Tab& t : tp.tabs)
      if (t.step != Tab::kIdle && now > t.deadline)
        tp.fail(t, "Chromium did not print " + tp.job_of(t).html.string() + " within " +
                       std::to_string(static_cast<int>(timeout_s)) + " s");
    if (!got) {
      // a browser that answers nothing while it has pages to print is not printing (nor
      // speaking the protocol)
      if (!busy) last_message = now;
      if (now - last_message > limit)
        throw PdfError("Chromium did not answer on the DevTools pipe");
      continue;
    }
    last_message = now;
    tp.on_message(*got);
  }
}

// prints the queue's pages: through one browser, then whatever it left one browser each
void drain(const std::string& chromium, PrintQueue& q, int parallel, double timeout_s,
           bool one_browser) {
  if (one_browser) {
    try {
      print_through_one_browser(chromium, q, parallel, timeout_s);
    } catch (const std::exception&) {
      // the pages not printed yet go one browser each (below)
    }
  }
  while (true) {
    std::unique_lock<std::mutex> lock(q.mu);
    size_t i = 0;
    while (i < q.jobs.size() && q.done[i]) ++i;
    if (i == q.jobs.size()) {
      if (q.closed) return;
      q.cv.wait(lock);
      continue;
    }
    const PdfJob job = q.jobs[i];
    q.next = std::max(q.next, i + 1);
    lock.unlock();
    std::string error;
    try {
      print_pdf(job.html, job.pdf, timeout_s);
    } catch (const std::exception& e) {
      error = e.what();
    }
    q.finish(i, error);
  }
}

}  // namespace

void print_pdf(const fs::path& html, const fs::path& pdf, double timeout_s) {
  const std::string chromium = chromium_or_throw();
  if (stopping()) throw PdfError("stopped by a signal");
  if (!fs::exists(html)) throw PdfError("cannot print " + html.string() + ": no such file");
  // a browser of its own for this page, speaking the protocol as print_pdfs' does: only
  // there can scripts be turned off and the page kept to its folder
  PrintQueue q;
  q.add({html, pdf}, {});
  q.closed = true;
  print_through_one_browser(chromium, q, 1, timeout_s);
  if (!q.errors[0].empty()) throw PdfError(q.errors[0]);
}

std::vector<std::string> print_pdfs(const std::vector<PdfJob>& jobs, int parallel,
                                    double timeout_s) {
  if (jobs.empty()) return {};
  const std::string chromium = chromium_or_throw();
  PrintQueue q;
  for (const PdfJob& j : jobs) q.add(j, {});
  q.closed = true;
  drain(chromium, q, parallel, timeout_s, jobs.size() > 1);
  return q.errors;
}

struct PdfPrinter::State {
  PrintQueue queue;
  std::thread thread;
  int parallel = 1;
  double timeout_s = 120;
};

PdfPrinter::PdfPrinter(int parallel, double timeout_s) : state_(std::make_unique<State>()) {
  state_->parallel = parallel;
  state_->timeout_s = timeout_s;
  const std::string chromium = chromium_or_throw();
  State* s = state_.get();
  s->thread = std::thread([s, chromium] {
    {
      // the browser starts with the first page (a run that prints nothing starts none)
      std::unique_lock<std::mutex> lock(s->queue.mu);
      s->queue.cv.wait(lock, [s] { return !s->queue.jobs.empty() || s->queue.closed; });
      if (s->queue.jobs.empty()) return;
    }
    drain(chromium, s->queue, s->parallel, s->timeout_s, true);
  });
}

PdfPrinter::~PdfPrinter() { finish(); }

void PdfPrinter::add(PdfJob job, std::function<void(const std::string&)> done) {
  state_->queue.add(std::move(job), std::move(done));
}

void PdfPrinter::finish() {
  if (!state_ || !state_->thread.joinable()) return;
  {
    std::lock_guard<std::mutex> lock(state_->queue.mu);
    state_->queue.closed = true;
    state_->queue.cv.notify_all();
  }
  state_->thread.join();
}

void kill_browsers() {
  g_stopping = true;  // no browser starts after this
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
  const fs::path tmp = temp_folder();
  // the shared temporary folder: only real folders of this user named as armstudy names
  // its profiles, removed through the open folder, never following a link
  const int tmp_fd = ::open(tmp.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (tmp_fd < 0) return 0;
  for (const std::string& f : sys::list_folder(tmp_fd)) {
    struct stat st {};
    if (f.rfind(kProfilePrefix, 0) != 0 || !sys::stat_at(tmp_fd, f, &st) || !S_ISDIR(st.st_mode) ||
        st.st_uid != ::geteuid())
      continue;
    const int dir = sys::open_folder_at(tmp_fd, f);
    if (dir < 0) continue;
    const int fd = ::openat(dir, kProfileLock, O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    ::close(dir);
    bool stale = false;
    if (fd >= 0) {
      stale = ::flock(fd, LOCK_EX | LOCK_NB) == 0;  // nobody prints with it
    } else {
      // no lock file: an earlier version's profile, or one being made right now
      stale =
          std::chrono::system_clock::now() - std::chrono::system_clock::from_time_t(st.st_mtime) >
          std::chrono::minutes(10);
    }
    if (stale) removed += sys::remove_tree_at(tmp_fd, f) > 0;
    if (fd >= 0) ::close(fd);
  }
  ::close(tmp_fd);
  return removed;
}

}  // namespace armstudy::report
