# SPDX-License-Identifier: BSD-3-Clause
# How each program runs as a test (short arguments so the suite stays fast).
add_test(NAME "app: grasp_transfer (small run)"
         COMMAND grasp_transfer --max-hypotheses 4 --jobs 2 --quiet --figures
                 --out ${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_small)
# The shipped recorded grasps (data/demonstrations) as the demonstrations (the first of each
# object), two methods; and the YCB objects (a smoke run: two of them, two hypotheses each).
add_test(NAME "app: grasp_transfer --demonstrations"
         COMMAND grasp_transfer --demonstrations ${PROJECT_SOURCE_DIR}/data/demonstrations
                 --max-hypotheses 1 --methods topological,transplant --judge builtin --jobs 2
                 --quiet --out ${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_demonstrations)
add_test(NAME "app: grasp_transfer on YCB objects (small run)"
         COMMAND grasp_transfer --objects ycb_tomato_soup_can,ycb_banana --max-hypotheses 2
                 --methods topological,transplant --judge builtin --jobs 2 --quiet
                 --out ${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_ycb)
add_test(NAME "app: record_demonstrations"
         COMMAND record_demonstrations --object can --count 1 --noise 1
                 --out ${CMAKE_CURRENT_BINARY_DIR}/recorded)
# Bad input: a clear message on stderr naming the option, and exit status 2 (nothing computed).
# Each case is "name|arguments separated by spaces|regex that stderr must match"; the tests get
# the label LABEL ("" for none).
function(expect_rejected program label)
  foreach(case IN LISTS ARGN)
    string(REPLACE "|" ";" parts "${case}")
    list(GET parts 0 name)
    list(GET parts 1 args)
    list(GET parts 2 expect)
    string(REPLACE " " ";" args "${args}")
    add_test(NAME "app: ${program} rejects ${name}"
             COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:${program}>;${args}"
                     "-DEXPECT=${expect}" -DSTATUS=2
                     -P ${PROJECT_SOURCE_DIR}/cmake/expect_failure.cmake)
    if(label)
      set_tests_properties("app: ${program} rejects ${name}" PROPERTIES LABELS ${label})
    endif()
  endforeach()
endfunction()
set(bad ${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_bad)
expect_rejected(grasp_transfer "" "unknown object|--objects anvil|--objects: unknown object \"anvil\""
                      "unknown method|--methods teleport|--methods: unknown method \"teleport\""
                      "duplicate object|--objects hammer,hammer|--objects: \"hammer\" is given twice"
                      "duplicate method|--methods topological,topological|--methods: \"topological\" is given twice"
                      "empty name|--objects hammer,,bottle|--objects: empty name"
                      "an option as a value|--out --jobs 2|--out: expected a value, got the option \"--jobs\""
                      "a missing value|--jobs|--jobs: expected a value"
                      "a repeated option|--out a --out b|--out: given twice"
                      "unknown option|--outt x|unknown option \"--outt\""
                      "bad shard|--shard 4/3|--shard: expected 1 <= K <= N"
                      "bad jobs|--jobs zero|--jobs: expected a number"
                      "too many jobs|--jobs 100000|--jobs: expected 1 to 1024"
                      "unwritable out|--out /proc/grasp_transfer|--out: cannot"
                      "--hands into an unwritable folder|--hands sdh --out /proc/grasp_transfer|--out: cannot create"
                      "unknown parameter|--set reach=1|unknown transfer parameter \"reach\""
                      "negative parameter|--set final_approach=-1|final_approach: must be in"
                      "parameter out of range|--set backoff=1e300|--set: backoff: must be in \\[0, 0.3\\]"
                      "parameter set twice|--set backoff=0.1 --set backoff=0.2|--set: backoff is set twice"
                      "parameter without value|--set final_approach|--set: expected NAME=VALUE"
                      "unknown winding reference|--winding-reference palm|--winding-reference: unknown reference"
                      "a human grip above ten|--human-grip 11|--human-grip: expected a multiple of the human hand's holding torques"
                      "resume with figures|--resume --figures|--figures: draws the grasps of this run only"
                      "merge without shards|merge --out x|merge: expected the shards' output folders"
                      "merge with a run option|merge --jobs 2 x|--jobs: not an option of merge"
                      "merge of a folder without a run|merge --out ${bad}-m /proc|merge: \"/proc\" holds no results.json of grasp_transfer"
                      "missing demonstrations|--demonstrations ${bad}-none.json|--demonstrations: [^:]*-none.json: file: no such file"
                      "demonstrations and objects|--demonstrations ${PROJECT_SOURCE_DIR}/data/demonstrations --objects hammer|--objects: not with --demonstrations"
                      "a folder without recordings|--demonstrations ${PROJECT_SOURCE_DIR}/docs/figures|--demonstrations: .* holds no keypoint files"
                      "a malformed recording|--demonstrations ${PROJECT_SOURCE_DIR}/tests/io/data/bad_keypoints.json|--demonstrations: [^:]*bad_keypoints.json: keypoints\\[3\\]: expected three numbers")
# Output folders that are refused before any work (exit 2), each prepared by the test: PREPARE is
# MKDIR=path or MKFILE=path (cmake/expect_failure.cmake), OUT the --out folder.
function(expect_refused_folder program name out prepare expect)
  add_test(NAME "app: ${program} rejects ${name}"
           COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:${program}>;--quiet;--out;${out}"
                   "-DEXPECT=${expect}" -DSTATUS=2 -D${prepare}
                   -P ${PROJECT_SOURCE_DIR}/cmake/expect_failure.cmake)
endfunction()
expect_refused_folder(grasp_transfer "results.json that is a folder" ${bad}-a
                      MKDIR=${bad}-a/results.json
                      "--out: \"[^\"]*results.json\" exists and is not a regular file")
expect_refused_folder(grasp_transfer "a folder of other files without --force" ${bad}-b
                      MKFILE=${bad}-b/notes.txt
                      "--out: .* holds no results.json of grasp_transfer; use --force")
expect_refused_folder(grasp_transfer "an output folder inside a file" ${bad}-c/file/out
                      MKFILE=${bad}-c/file "--out: cannot create the folder")
# --help prints the usage with every parameter's range, and exits 0.
add_test(NAME "app: grasp_transfer --help" COMMAND grasp_transfer --help)
set_tests_properties("app: grasp_transfer --help" PROPERTIES
                     PASS_REGULAR_EXPRESSION "backoff +0.03 +\\[0, 0.3\\]")
# ... and the hands, those of the programs beside it (grasp_transfer-<hand>) too.
if(NOT TOPOGRASP_SANITIZE)
  add_test(NAME "app: grasp_transfer --help lists the hand programs beside it"
           COMMAND grasp_transfer --help)
  set_tests_properties("app: grasp_transfer --help lists the hand programs beside it" PROPERTIES
                       PASS_REGULAR_EXPRESSION
                       "sdh +schunk_sdh [(]the default[)]\n  allegro +run by grasp_transfer-allegro\n  barrett +run by grasp_transfer-barrett\n")
endif()
# Two shards of a small run merged into one output folder (merge_results checks the document
# against the whole run in tests/grasp/test_resume_merge.cpp); a shard missing is refused.
add_test(NAME "app: grasp_transfer shards merged"
         COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:grasp_transfer>
                 -DDIR=${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_shards
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/grasp_transfer/shard_merge.cmake)
# The Slurm job scripts (apps/grasp_transfer/slurm), run without Slurm as the scheduler would run them.
add_test(NAME "app: slurm job scripts"
         COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:grasp_transfer>
                 -DDIR=${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_slurm
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/grasp_transfer/slurm/run_locally.cmake)
# grasp_transfer --hand: a small run with each other shipped hand (one stable bottle
# demonstration), with figures; what only the SDH on the arm runs refused for another hand.
foreach(hand IN ITEMS barrett allegro leap shadow)
  add_test(NAME "app: grasp_transfer --hand ${hand} (small run)"
           COMMAND grasp_transfer --hand ${hand} --objects bottle --max-hypotheses 2
                   --methods topological,transplant,virtual_finger --jobs 2 --quiet --figures
                   --out ${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_${hand})
  set_tests_properties("app: grasp_transfer --hand ${hand} (small run)" PROPERTIES
                       LABELS end_to_end PASS_REGULAR_EXPRESSION "results in .*grasp_transfer_${hand}")
endforeach()
expect_rejected(grasp_transfer end_to_end
                "an unknown hand|--hand robotiq|--hand: no hand \"robotiq\" in this program \\(sdh, allegro, barrett, leap, shadow\\)"
                "a method on the arm for another hand|--hand allegro --methods closed_windings|methods: \"closed_windings\" runs with the SDH on the arm only"
                "the arm setting for another hand|--hand leap --setting arm|arm_setting: the arm carries the SDH only")
# --hands: the same run for several hands and the table of every hand; its shards merged; what
# only the SDH runs refused before any hand runs.
add_test(NAME "app: grasp_transfer --hands (small run)"
         COMMAND grasp_transfer --hands sdh,barrett --objects bottle --max-hypotheses 2
                 --methods topological,transplant --jobs 2 --quiet
                 --out ${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_hands)
set_tests_properties("app: grasp_transfer --hands (small run)" PROPERTIES
                     LABELS end_to_end PASS_REGULAR_EXPRESSION "every hand's table in .*hands.md")
add_test(NAME "app: grasp_transfer --hands shards merged"
         COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:grasp_transfer>
                 -DDIR=${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_hands_shards
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/grasp_transfer/hands_merge.cmake)
set_tests_properties("app: grasp_transfer --hands shards merged" PROPERTIES LABELS end_to_end)
expect_rejected(grasp_transfer end_to_end
                "a method on the arm for a hand of --hands|--hands sdh,barrett --methods topological,closed_windings|--hands: barrett: --methods closed_windings runs with the SDH on the arm only"
                "--hands with --hand|--hands sdh,barrett --hand sdh|--hands: not with --hand")
# --source: the SDH's stable topological transfers of the --hands run as the demonstrations, to
# the Barrett; what does not fit refused.
add_test(NAME "app: grasp_transfer --source (the SDH demonstrates to the Barrett)"
         COMMAND grasp_transfer --hand barrett --source ${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_hands/sdh
                 --methods topological,transplant --jobs 2 --quiet --figures
                 --out ${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_source)
set_tests_properties("app: grasp_transfer --source (the SDH demonstrates to the Barrett)" PROPERTIES
                     LABELS end_to_end DEPENDS "app: grasp_transfer --hands (small run)"
                     PASS_REGULAR_EXPRESSION "results in .*grasp_transfer_source")
expect_rejected(grasp_transfer end_to_end
                "a source that does not exist|--source ${bad}-none|--source: .*-none. does not exist"
                "a source with --hypotheses|--source ${bad}-none --hypotheses box|--hypotheses: not with --source"
                "a source that is not a run|--source ${PROJECT_SOURCE_DIR}/data/schemas/results.schema.json|--source: .*results.schema.json: generator: missing")
# A hand whose program (grasp_transfer-<hand>) is not built: grasp_transfer, alone in a folder,
# says which target builds it. Not in the sanitizer build, which has no other hand.
if(NOT TOPOGRASP_SANITIZE)
  add_test(NAME "app: grasp_transfer names the target of a hand program not built"
           COMMAND ${CMAKE_COMMAND}
                   "-DCOMMAND=$<TARGET_FILE:grasp_transfer>;--hand;barrett;--quiet"
                   "-DEXPECT=--hand: the program of the hand \"barrett\", grasp_transfer-barrett, is not built: cmake --build --preset release --target grasp_transfer-barrett"
                   -DSTATUS=2 -DCOPY_TO=${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_alone
                   -P ${PROJECT_SOURCE_DIR}/cmake/expect_failure.cmake)
endif()
# Past a file-size limit a run into the small run's folder fails with a message and leaves that
# run's files as they were (its outputs are staged and committed as one).
add_test(NAME "app: grasp_transfer fails whole past a file-size limit"
         COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:grasp_transfer>
                 -DSOURCE=${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_small
                 -DDIR=${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_file_limit
                 -P ${CMAKE_CURRENT_SOURCE_DIR}/grasp_transfer/file_limit.cmake)
set_tests_properties("app: grasp_transfer fails whole past a file-size limit" PROPERTIES
                     DEPENDS "app: grasp_transfer (small run)" LABELS end_to_end)
# record_demonstrations is not built by the sanitizer build: its refusals are checked in the
# Release build with its end-to-end run.
expect_rejected(record_demonstrations end_to_end
                "a repeated option|--object can --count 1 --count 2|--count: given twice"
                "an option as a value|--object --count|--object: expected a value"
                "unknown object|--object anvil|--object: unknown object \"anvil\"")

# The programs' runs that simulate grasps are the end-to-end tests (label end_to_end): they run
# once, in the Release build of the README's test command. The sanitize preset leaves them out
# (tests/CMakeLists.txt) and runs this shortened end-to-end run instead (label smoke): one
# hypothesis of each built-in object through the whole program, every method, both judges (MuJoCo
# where it is found), figures and the results page.
set_tests_properties("app: grasp_transfer (small run)"
                     "app: grasp_transfer --demonstrations"
                     "app: grasp_transfer on YCB objects (small run)"
                     "app: record_demonstrations"
                     "app: grasp_transfer shards merged" "app: slurm job scripts"
                     PROPERTIES LABELS end_to_end)
add_test(NAME "app: grasp_transfer (smoke)"
         COMMAND grasp_transfer --max-hypotheses 1 --jobs 2 --quiet --figures
                 --out ${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_smoke)
set_tests_properties("app: grasp_transfer (smoke)" PROPERTIES LABELS smoke)
