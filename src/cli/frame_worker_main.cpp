// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
// armstudy-frames: the helper process that draws frames beside armstudy (scene/frame_worker.hpp).
// Started by armstudy with its socket as standard input and output and armstudy's process id
// as the one argument; not meant to be run by hand.
#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cli/process_memory.hpp"
#include "scene/frame_worker.hpp"

int main(int argc, char** argv) {
  armstudy::cli::keep_freed_memory();
  // dies with the process that started it, even one killed with SIGKILL
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (argc != 2 || std::to_string(::getppid()) != argv[1]) {
    std::fprintf(stderr, "armstudy-frames: started by armstudy only (its frame helper)\n");
    return 2;
  }
  return armstudy::scene::run_frame_worker(0, 1);
}
