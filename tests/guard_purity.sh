#!/bin/sh
# core and studies are pure: no file or console I/O, no YAML, no MuJoCo (README, Layout).
cd "$1" || exit 2
hits=$(grep -rnE '#include <(fstream|iostream)>|yaml-cpp|mujoco|std::cout|std::cerr|printf\(' src/core src/studies)
if [ -n "$hits" ]; then
  echo "impure includes or output in src/core or src/studies:"; echo "$hits"; exit 1
fi
echo "src/core and src/studies are pure"
