#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The compile time of representative user translation units (docs/benchmarks.md, "Compile time"):
# each file is compiled on its own, one after the other, with the release flags of a user's build,
# and its CPU time (user + system) and peak memory are printed as a Markdown table.
#
#   benchmarks/compile_time.sh                 # g++ -O2, every unit
#   CXX=clang++ benchmarks/compile_time.sh     # another compiler
#   FLAGS="-O3 -DNDEBUG" benchmarks/compile_time.sh tour_kinematics sdh_on_arm   # some units
#   REPEAT=3 benchmarks/compile_time.sh        # each unit 3 times, the least CPU time
#
# On a shared virtual machine the same compilation varies by tens of per cent from one hour to the
# next: compare two trees unit by unit, one right after the other (docs/benchmarks.md), and take
# the least of a few repeats.
# The units (benchmarks/compile_time/*.cpp, and three files of the repository):
#   tour_kinematics         the README tour's first snippet: <topograsp/topograsp.hpp>, SDH FK
#   hand_kinematics         one imported hand's kinematics and the windings of its curves
#   imported_hand_transfer  human demonstrations transferred to an imported hand by every method
#   sdh_on_arm              the README tour's transfer: the SDH on the arm, transfer_topological
#   grasp_transfer_sdh      the main example's SDH, apps/grasp_transfer/hands/sdh.cpp
#   hand_program            one imported hand's grasp_transfer (apps/grasp_transfer/hands/allegro.cpp,
#                           as the program unit topograsp_add_hand_program generates for a user's hand)
#   hand_compiled           that hand's transfer steps compiled once (compiled/allegro.cpp, as the
#                           hand's second generated unit)
#   hand_independent        the hand-independent templates compiled once, compiled/hand_independent.cpp
#   grasp_transfer_human    the human hand's scenes and MuJoCo judge, human.cpp
#   grasp_transfer_main     the program's command line and merge, main.cpp
#   test_<module>           a test module as CMake builds it (its files in one unity unit)
# Nothing is built or run besides the compiler; objects go to a temporary folder.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cxx=${CXX:-g++}
flags=${FLAGS:-"-O2 -DNDEBUG"}
repeat=${REPEAT:-1}
units=("$@")
if ((${#units[@]} == 0)); then
  units=(tour_kinematics hand_kinematics imported_hand_transfer sdh_on_arm grasp_transfer_sdh
         hand_program hand_compiled hand_independent grasp_transfer_human grasp_transfer_main
         test_any_hand)
fi
if [[ ! -x /usr/bin/time ]]; then
  echo "compile_time.sh: needs GNU time (/usr/bin/time, Debian package time)" >&2
  exit 2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

common=(-std=c++20 -I"$root/include" -isystem /usr/include/eigen3
        "-DTOPOGRASP_DATA_DIR=\"$root/data\"")
# The optional peers, as the project's build passes them where they are installed.
optional=()
if [[ -f /usr/include/mujoco/mujoco.h ]]; then optional+=(-DTOPOGRASP_HAVE_MUJOCO); fi
if [[ -f /usr/include/libqhull_r/libqhull_r.h ]]; then optional+=(-DTOPOGRASP_HAVE_QHULL); fi

echo "| unit | CPU s | peak MB |"
echo "| --- | --- | --- |"
for unit in "${units[@]}"; do
  extra=()
  case $unit in
    grasp_transfer_sdh | hand_program | hand_compiled | hand_independent | grasp_transfer_human | \
      grasp_transfer_main)
      case $unit in
        grasp_transfer_sdh) source=$root/apps/grasp_transfer/hands/sdh.cpp ;;
        hand_program) source=$root/apps/grasp_transfer/hands/allegro.cpp ;;
        hand_compiled) source=$root/apps/grasp_transfer/compiled/allegro.cpp ;;
        hand_independent) source=$root/apps/grasp_transfer/compiled/hand_independent.cpp ;;
        grasp_transfer_human) source=$root/apps/grasp_transfer/human.cpp ;;
        grasp_transfer_main) source=$root/apps/grasp_transfer/main.cpp ;;
      esac
      # As the build compiles them: the hand-independent templates and the shipped hands'
      # transfer steps compiled once (apps/CMakeLists.txt).
      extra=(-I"$root/apps" -DTOPOGRASP_EXTERN_HAND_INDEPENDENT -DEIGEN_RUNTIME_NO_MALLOC
        "${optional[@]}")
      ;;
    test_*)
      module=${unit#test_}
      if [[ ! -d $root/tests/$module ]]; then
        echo "compile_time.sh: no test module tests/$module" >&2
        exit 2
      fi
      source=$work/$unit.cpp
      # The modules that link the compiled templates (tests/CMakeLists.txt) declare them
      # compiled elsewhere; those that transfer to shipped hands start with shipped_hands.hpp.
      case $module in
        any_hand | apps | grasp) echo "#include <grasp_transfer/shipped_hands.hpp>" ;;
        *) : ;;
      esac > "$source"
      for file in "$root"/tests/"$module"/*.cpp; do echo "#include \"$file\""; done >> "$source"
      extra=(-I"$root/tests" -I"$root/apps" -DEIGEN_RUNTIME_NO_MALLOC "${optional[@]}")
      case $module in
        any_hand | apps | grasp | evaluation) extra+=(-DTOPOGRASP_EXTERN_HAND_INDEPENDENT) ;;
      esac
      ;;
    *) source=$root/benchmarks/compile_time/$unit.cpp ;;
  esac
  if [[ ! -f $source ]]; then
    echo "compile_time.sh: no unit $unit ($source)" >&2
    exit 2
  fi
  : > "$work/times"
  for ((r = 0; r < repeat; ++r)); do
    # shellcheck disable=SC2086 # $flags is a list of flags
    if ! /usr/bin/time -o "$work/time" -f "%U %S %M" "$cxx" "${common[@]}" $flags "${extra[@]}" \
         -c "$source" -o "$work/unit.o" 2> "$work/log"; then
      cat "$work/log" >&2
      echo "compile_time.sh: $unit does not compile" >&2
      exit 1
    fi
    tail -n 1 "$work/time" >> "$work/times"
  done
  awk -v unit="$unit" 'NR == 1 || $1 + $2 < best { best = $1 + $2; mb = $3 / 1024 }
                       END { printf "| %s | %.1f | %d |\n", unit, best, mb }' "$work/times"
done
