// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cli/interrupt.hpp"

#include <signal.h>
#include <string.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <thread>

#include "report/case_report.hpp"
#include "sys/scratch_dir.hpp"

namespace armstudy::cli {

void install_interrupt_cleanup() {
  static sigset_t set;
  sigemptyset(&set);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&set, s);
  if (::pthread_sigmask(SIG_BLOCK, &set, nullptr) != 0) return;
  std::thread([] {
    int sig = 0;
    while (::sigwait(&set, &sig) != 0) {
    }
    sys::stop_scratch();  // before the browsers die and let the threads that wait on them go
    report::kill_browsers();
    sys::remove_own_scratch();  // waits for a folder swap under way to finish
    std::fprintf(stderr,
                 "\narmstudy: stopped by %s; unfinished output removed, earlier reports kept\n",
                 sigabbrev_np(sig) ? (std::string("SIG") + sigabbrev_np(sig)).c_str() : "a signal");
    std::fflush(stderr);
    ::_exit(128 + sig);
  }).detach();
}

}  // namespace armstudy::cli
