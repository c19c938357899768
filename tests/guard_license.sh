#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Copyright 2026 The armstudy authors
#
# Licence guard: armstudy is Apache-2.0 (LICENSE). Every tracked source file (C++, CMake,
# shell, Python, the report's stylesheet) names its licence and copyright in its first
# lines, after a #! line if it has one. The HTML templates are exempt: a comment in them
# would be copied into every report page, which is the user's document, not armstudy's.
cd "$1" || exit 2
list() {
  if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    git ls-files -- '*.cpp' '*.hpp' '*.hpp.in' '*.h' '*.c' 'CMakeLists.txt' '*/CMakeLists.txt' \
      '*.cmake' '*.sh' '*.py' '*.sbatch' '.ci/run' '*.supp' '*.css'
  else
    find . \( -name .git -o -name build -o -name out \) -prune -o -type f \( -name '*.cpp' \
      -o -name '*.hpp' -o -name '*.hpp.in' -o -name '*.h' -o -name '*.c' -o -name CMakeLists.txt \
      -o -name '*.cmake' -o -name '*.sh' -o -name '*.py' -o -name '*.sbatch' -o -name '*.supp' \
      -o -name '*.css' -o -path ./.ci/run \) -print | sed 's|^\./||'
  fi
}
# the files whose first 5 lines lack either line (one awk over all of them)
files=$(list | while read -r f; do [ -f "$f" ] && echo "$f"; done)
lacking=$(echo "$files" | tr '\n' '\0' | xargs -0 awk '
  FNR == 1 { seen[FILENAME] = 1 }
  FNR <= 5 && /SPDX-License-Identifier: Apache-2.0/ { spdx[FILENAME] = 1 }
  FNR <= 5 && /Copyright 2026 The armstudy authors/ { copy[FILENAME] = 1 }
  END { for (f in seen) if (!(spdx[f] && copy[f])) print f }' | sort)
missing=0
for f in $lacking; do
  case $f in
    *.cpp | *.hpp | *.hpp.in | *.h | *.c) c='//'; e='' ;;
    *.css) c='/*'; e=' */' ;;
    *) c='#'; e='' ;;
  esac
  where="at the top of $f"
  [ "$(head -c 2 "$f")" = "#!" ] && where="in $f, right after its #! line"
  # the stylesheet's first line is the mark armstudy knows its own copy by (owned_output.cpp)
  case $f in *.css) where="in $f, right after its first line" ;; esac
  echo "$f: no licence lines; add these two lines $where:"
  echo "$c SPDX-License-Identifier: Apache-2.0$e"
  echo "$c Copyright 2026 The armstudy authors$e"
  missing=$((missing + 1))
done
if [ "$missing" -gt 0 ]; then
  echo "$missing source file(s) without the licence lines (LICENSE: Apache-2.0)"
  exit 1
fi
echo "every source file names its licence (Apache-2.0)"
