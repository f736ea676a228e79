#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Makes the shipped imported hands again (include/topograsp/model/models/imported/*.hpp): each
# MuJoCo Menagerie file with its hand description (data/hands/*.json), through
# topograsp_import_hand. docs/models.md, "Today's hands".
#
#   tools/import_shipped_hands.sh MENAGERIE_DIR [TOOL]
#
# MENAGERIE_DIR: a checkout of github.com/google-deepmind/mujoco_menagerie at the commit below
# (its files are not in this repository); TOOL: topograsp_import_hand (default
# build/release/topograsp_import_hand). The headers are written in place; `git diff` shows what
# changed.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
if (($# < 1 || $# > 2)); then
  echo "usage: tools/import_shipped_hands.sh MENAGERIE_DIR [TOOL]" >&2
  exit 2
fi
menagerie=$1
tool=${2:-$root/build/release/topograsp_import_hand}
commit=66384c6b8581c811a7b1eb63bcf4fa944fa43602
if [[ ! -x $tool ]]; then
  echo "import_shipped_hands.sh: no topograsp_import_hand at $tool (build it: cmake --build --preset release --target topograsp_import_hand)" >&2
  exit 2
fi
out=$root/include/topograsp/model/models/imported
source="Source: MuJoCo Menagerie (github.com/google-deepmind/mujoco_menagerie, commit $commit),"

# import NAME FILE SPDX SOURCE_LINE [OPTION...]
import() {
  local name=$1 file=$2 spdx=$3 line=$4
  shift 4
  if [[ ! -f $menagerie/$file ]]; then
    echo "import_shipped_hands.sh: no $file in $menagerie" >&2
    exit 1
  fi
  local description=$root/data/hands/$name.json
  "$tool" "$menagerie/$file" "$@" --description "$description" --out "$out/${file%%/*}.hpp" \
    --namespace "topograsp::models::imported::${file%%/*}" \
    --comment "SPDX-License-Identifier: $spdx" --comment "$source" --comment "$line"
}

import allegro_hand wonik_allegro/right_hand.xml \
  "BSD-2-Clause (the source model's licence: Copyright (c) 2016, SimLab)" \
  "wonik_allegro/right_hand.xml, derived from SimLab's allegro_hand_ros URDF; described by data/hands/allegro_hand.json. Numbers only; docs/models.md."
import leap_hand leap_hand/right_hand.xml \
  "MIT (the source model's licence: Copyright 2023 Ananye Agarwal)" \
  "leap_hand/right_hand.xml, derived from dexsuite/dex-urdf's LEAP hand URDF; described by data/hands/leap_hand.json. Numbers only; docs/models.md."
import shadow_hand shadow_hand/right_hand.xml \
  "Apache-2.0 (the source model's licence: Copyright 2022 Shadow Robot Company Ltd)" \
  "shadow_hand/right_hand.xml (Shadow Dexterous Hand E3M5), imported from its palm (--root rh_palm); described by data/hands/shadow_hand.json. Numbers only; docs/models.md." \
  --root rh_palm
