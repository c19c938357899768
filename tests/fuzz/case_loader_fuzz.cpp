// libFuzzer target for the case and sweep loaders: every input is read (1) as a case file
// by app::load_case_text, (2) as a sweep file by app::load_sweep, over a fixed valid base
// case, and (3) as the base case of a fixed sweep. A loader may refuse an input only with
// cases::CaseErrors, each error with a message; anything else (another exception, a crash,
// a leak, undefined behaviour, a hang, a runaway allocation) is a finding.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "app/pipeline.hpp"
#include "cases/case_error.hpp"
#include "cli/sweep.hpp"

namespace {
namespace fs = std::filesystem;

const char* kBase =
    "study: placement\nname: base\nplacement: {length_fraction: 0.5, nx_s: 4, samples: 21}\n";
const char* kSweep =
    "sweep: fuzz\nbase: fuzz-base.yaml\nmode: grid\naxes:\n"
    "  - path: placement.length_fraction\n    values: [0.4, 0.6]\n";

const fs::path& work_dir() {
  static const fs::path dir = [] {
    const fs::path d = fs::temp_directory_path() / ("armstudy-fuzz-" + std::to_string(getpid()));
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << text;
}

void expect_only_case_errors(void (*load)(const std::string&), const std::string& arg) {
  try {
    load(arg);
  } catch (const armstudy::cases::CaseErrors& e) {
    if (e.errors().empty()) std::abort();  // refused without saying why
    for (const auto& err : e.errors())
      if (err.message.empty()) std::abort();
  }
  // any other exception escapes: libFuzzer reports it as a crash
}

void load_text(const std::string& text) { armstudy::app::load_case_text(text, "fuzz.yaml"); }
void load_sweep_file(const std::string& path) { armstudy::app::load_sweep(path); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  expect_only_case_errors(load_text, text);
  const fs::path& d = work_dir();
  // the input as a sweep over the fixed base
  write(d / "fuzz-base.yaml", kBase);
  write(d / "fuzz-sweep.yaml", text);
  expect_only_case_errors(load_sweep_file, (d / "fuzz-sweep.yaml").string());
  // the input as the base of the fixed sweep
  write(d / "fuzz-base.yaml", text);
  write(d / "fuzz-sweep.yaml", kSweep);
  expect_only_case_errors(load_sweep_file, (d / "fuzz-sweep.yaml").string());
  return 0;
}
