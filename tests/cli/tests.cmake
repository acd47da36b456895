# The CLI's tests, by subcommand. Files come from make_fixtures.cmake (v0 seed 1 unless named).
# A regex matches a ';' of the output with '.': ';' separates the items of a CMake list.
string(ASCII 27 esc)  # the start of a terminal colour sequence

# ---- usage and help -------------------------------------------------------------------------
symcr_cli_test(no_subcommand EXIT 2 ARGS EXPECT "a subcommand is needed")
symcr_cli_test(unknown_option EXIT 2 ARGS inspect --bogus ${files}/v0.ckpt
               EXPECT "Unknown command line argument '--bogus'")
symcr_cli_test(missing_argument EXIT 2 ARGS inspect EXPECT "Not enough positional")
symcr_cli_test(help EXIT 0 ARGS --help EXPECT "inspect" "verify" "diff" "plan" "convert"
               "Exit codes")
symcr_cli_test(inspect_help EXIT 0 ARGS inspect --help EXPECT "--json" "--slot" "--key-file" "--key-id"
               REJECT "--schema" "--strict")
symcr_cli_test(plan_help EXIT 0 ARGS plan --help EXPECT "--schema" "--strict" "--json" "--key-file")
symcr_cli_test(convert_help EXIT 0 ARGS convert --help
               EXPECT "--schema" "--initial" "--writer-schema" "--inline-schema" "--strict"
                      "--key-file" "--key-ring" "--counter")

# ---- inspect --------------------------------------------------------------------------------
symcr_cli_test(inspect_checkpoint EXIT 0 ARGS inspect ${files}/v0.ckpt
  EXPECT "format_version +1\n"
         "sequence +0\n"
         "time +20[0-9][0-9]-[01][0-9]-[0-3][0-9]T[0-2][0-9]:[0-5][0-9]:[0-6][0-9]\\.[0-9]+Z\n"
         "schema_hash +[0-9a-f]+\n"
         "schema +inline, 18 types, 2 roots"
         "checksum +ok \\(crc32c [0-9a-f]+\\)"
         "copter.ticks +=  *1001\n"
         "copter.mode +=  *AUTO\n"
         "copter.mission.items\\[3\\].lat += 42.28\n"
         "copter.mission.items\\[1\\].alt += 100.5\n"
         "copter.mission.items\\[0\\].alt += 100\n"
         "copter.mission.name += \"ISTAR\"\n"
         "copter.mission.log\\[2\\] += 1\n"
         "copter.armed_ms += 5000000001\n"
         "copter.target += -> copter.mission.items\\[2\\]\n"
         "telemetry.rssi += -70\n"
  REJECT "${esc}\\[")
symcr_cli_test(inspect_json EXIT 0 JSON ARGS inspect --json ${files}/v0.ckpt
  EXPECT "\"kind\": \"checkpoint\""
         "\"format_version\": 1"
         "\"path\": \"copter.mode\",[ \n]*\"type\": \"FlightMode\",[ \n]*\"value\": \"AUTO\""
         "\"path\": \"copter.mission.items\\[3\\].lat\",[ \n]*\"type\": \"float64\",[ \n]*\"value\": 42.28"
         "\"path\": \"copter.target\",[ \n]*\"type\": \"Waypoint\\*\",[ \n]*\"value\": \"-> copter.mission.items\\[2\\]\"")
symcr_cli_test(inspect_store EXIT 0 ARGS inspect ${files}/v0.store
  EXPECT "slots +4 x 4096 bytes"
         "schema_area 0 +hash [0-9a-f]+, [0-9]+ bytes, 18 types, 2 roots"
         "restore_latest +slot 1 \\(sequence 6\\)"
         "\n0 +valid +5 "
         "\n1 +valid +6 .*<- shown"
         "\n2 +valid +3 "
         "\nslot 1\n"
         "schema +store area 0"
         "copter.ticks += 1006\n")
symcr_cli_test(inspect_store_slot EXIT 0 ARGS inspect --slot 2 ${files}/v0.store
  EXPECT "\n2 +valid +3 .*<- shown" "copter.ticks += 1003\n")
symcr_cli_test(inspect_store_no_such_slot EXIT 2 ARGS inspect --slot 9 ${files}/v0.store
  EXPECT "has 4 slots; there is no slot 9")
symcr_cli_test(inspect_store_json EXIT 0 JSON ARGS inspect --json ${files}/v0.store
  EXPECT "\"kind\": \"store\"" "\"restore_latest_slot\": 1" "\"selected_slot\": 1"
         "\"value\": 1006")
symcr_cli_test(inspect_torn_store EXIT 0 ARGS inspect ${files}/torn.store
  EXPECT "restore_latest +slot 0 \\(sequence 5\\)"
         "\n1 +corrupt +- .*checksum mismatch"
         "copter.ticks += 1005\n")
symcr_cli_test(inspect_torn_slot EXIT 2 ARGS inspect --slot 1 ${files}/torn.store
  EXPECT "slot 1 is corrupt: checksum mismatch")
# crashed.store: a start restored 6, the next passed over 6 and restored 5, neither confirmed.
# The next start counts that as a crash too: it passes over 5 and 6 and restores 4.
symcr_cli_test(inspect_crash_loop_store EXIT 0 ARGS inspect ${files}/crashed.store
  EXPECT "restore_journal +restore of #5 unconfirmed. suspect #6 \\(1 fallback\\). fallback depth 3\n"
         "next_start +counts the unconfirmed restore of #5 as a crash: suspect #5 to #6 \\(2 fallbacks\\)\n"
         "restore_latest +slot 3 \\(sequence 4\\)"
         "\n0 +valid +5 .*crash-loop fallback: suspect, the last start restored it"
         "\n1 +valid +6 .*crash-loop fallback: suspect"
         "\n3 +valid +4 .*<- shown"
         "copter.ticks += 1004\n")
symcr_cli_test(inspect_crash_loop_store_json EXIT 0 JSON ARGS inspect --json ${files}/crashed.store
  EXPECT "\"unconfirmed\": 5" "\"suspect_high\": 6" "\"passed_over\": true"
         "\"next_start\": {[ \n]*\"counts_crash\": true,[ \n]*\"gives_up\": false"
         "\"journal\": {[ \n]*\"unconfirmed\": 0,[ \n]*\"suspect_low\": 5,[ \n]*\"suspect_high\": 6"
         "\"restore_latest_slot\": 3" "\"selected_slot\": 3")
symcr_cli_test(inspect_empty_store EXIT 2 ARGS inspect ${files}/empty.store
  EXPECT "restore_latest +none \\(nothing would be restored: no slot holds a restorable checkpoint\\)"
         "\n0 +empty +- " "error: .*empty.store: nothing would be restored")
symcr_cli_test(inspect_patched_store EXIT 0 ARGS inspect ${files}/patched.store
  EXPECT "schema_area 0 +hash [0-9a-f]+, [0-9]+ bytes, 18 types"
         "schema_area 1 +hash [0-9a-f]+, [0-9]+ bytes, 17 types"
         "restore_latest +slot 3 \\(sequence 4\\)"
         "\n0 +valid +1 .* area 0" "\n3 +valid +4 .* area 1 +<- shown"
         "copter.geofence += 150\n")
symcr_cli_test(inspect_schema_file EXIT 0 ARGS inspect ${files}/v1.schema
  EXPECT "schema file" "payload_size +0\n" "copter +Copter\n" "telemetry +Telemetry\n")
symcr_cli_test(inspect_corrupt EXIT 2 ARGS inspect ${files}/corrupt.ckpt
  EXPECT "symcr: error: .*corrupt.ckpt: checksum mismatch" REJECT "copter.ticks")
symcr_cli_test(inspect_truncated EXIT 2 ARGS inspect ${files}/truncated.ckpt
  EXPECT "truncated: header says [0-9]+ bytes, 100 available")
symcr_cli_test(inspect_not_a_checkpoint EXIT 2 ARGS inspect ${files}/not-a-checkpoint.txt
  EXPECT "not a symcr checkpoint or store \\(bad magic\\)")
symcr_cli_test(inspect_missing EXIT 2 ARGS inspect ${files}/no-such-file
  EXPECT "cannot open .*no-such-file: No such file or directory")
# A program refuses a checkpoint or store behind a symlink; the CLI says so and names the target.
symcr_cli_test(inspect_symlink EXIT 2 ARGS inspect ${files}/latest.ckpt
  EXPECT "latest.ckpt: it is a symbolic link, which symcr does not follow; a program refuses it too: give the path it points to, .*v0.ckpt"
  REJECT "copter.ticks")
symcr_cli_test(verify_symlinked_store EXIT 2 ARGS verify ${files}/latest.store
  EXPECT "latest.store: it is a symbolic link, which symcr does not follow"
  REJECT "restore_latest")
symcr_cli_test(inspect_no_color EXIT 0 ARGS inspect ${files}/v0.ckpt ENV NO_COLOR=1
  REJECT "${esc}\\[")

# ---- verify ---------------------------------------------------------------------------------
symcr_cli_test(verify_checkpoint EXIT 0 ARGS verify ${files}/v0.ckpt
  EXPECT "record +ok +format 1, [0-9]+ bytes, checksum ok"
         "schema +ok +inline, hash [0-9a-f]+, 18 types, 2 roots"
         "payload +ok +[0-9]+ bytes, [0-9]+ values decoded"
         "\nvalid\n")
symcr_cli_test(verify_schema_file EXIT 0 ARGS verify ${files}/v0.schema
  EXPECT "^schema " "payload +ok +none \\(a schema file\\)" "\nvalid\n")
symcr_cli_test(verify_corrupt EXIT 1 ARGS verify ${files}/corrupt.ckpt
  EXPECT "record +FAILED +Checksum: checksum mismatch" "\ninvalid\n" REJECT "payload")
symcr_cli_test(verify_truncated EXIT 1 ARGS verify ${files}/truncated.ckpt
  EXPECT "record +FAILED +Truncated" "\ninvalid\n")
symcr_cli_test(verify_not_a_checkpoint EXIT 1 ARGS verify ${files}/not-a-checkpoint.txt
  EXPECT "invalid: .*bad magic")
symcr_cli_test(verify_missing EXIT 2 ARGS verify ${files}/no-such-file EXPECT "cannot open")
symcr_cli_test(verify_empty_store EXIT 1 ARGS verify ${files}/empty.store
  EXPECT "\ninvalid: nothing would be restored: no slot holds a restorable checkpoint\n")
symcr_cli_test(verify_json EXIT 1 JSON ARGS verify --json ${files}/corrupt.ckpt
  EXPECT "\"valid\": false" "\"check\": \"record\",[ \n]*\"ok\": false")
symcr_cli_test(verify_store EXIT 0 ARGS verify ${files}/v0.store
  EXPECT "restore_latest +slot 1 \\(sequence 6\\)" "\nvalid\n")
symcr_cli_test(verify_torn_store EXIT 1 ARGS verify ${files}/torn.store
  EXPECT "restore_latest +slot 0 \\(sequence 5\\)"
         "\n1 +corrupt +- .*checksum mismatch"
         "\ninvalid: 1 damaged slot")
symcr_cli_test(verify_torn_store_json EXIT 1 JSON ARGS verify --json ${files}/torn.store
  EXPECT "\"valid\": false" "\"damaged_slots\": 1" "\"restore_latest_slot\": 0")

# ---- diff -----------------------------------------------------------------------------------
symcr_cli_test(diff_same EXIT 0 ARGS diff ${files}/v0.ckpt ${files}/v0.ckpt
  EXPECT "no differences \\([0-9]+ values\\)")
symcr_cli_test(diff_seeds EXIT 1 ARGS diff ${files}/v0.ckpt ${files}/v0-seed2.ckpt
  EXPECT "\n +path +a +b\n"
         "\n~ +copter.ticks +1001 +1002\n"
         "\n~ +copter.mode +AUTO +LAND\n"
         "\n~ +copter.mission.log\\[2\\] +1 +2\n"
  REJECT "copter.mission.name" "\n[+-] ")
symcr_cli_test(diff_builds EXIT 1 ARGS diff ${files}/v0.ckpt ${files}/v1.ckpt
  EXPECT "\n~ +copter.ticks +1001 +2001 +\\(int32 -> int64\\)\n"
         "\n- +copter.armed_ms +5000000001 +\\(absent\\)\n"
         "\n- +copter.mission.items\\[3\\].lat +42.28 +\\(absent\\)\n"
         "\n- +copter.mission.current +1 +\\(absent\\)\n"
         "\n\\+ +copter.mission.active_index +\\(absent\\) +1\n"
         "\n\\+ +copter.geofence +\\(absent\\) +150\n"
         "\n~ +copter.target +-> copter.mission.items\\[2\\] +-> copter.mission.items\\[1\\]\n"
         "9 difference\\(s\\): 2 changed, 5 removed, 2 added"
  REJECT "copter.mode" "copter.battery" "telemetry.rssi")
symcr_cli_test(diff_store_and_file EXIT 1 ARGS diff --slot-a 0 ${files}/v0.store ${files}/v0.ckpt
  EXPECT "a +.*v0.store slot 0 \\(sequence 5" "\n~ +copter.ticks +1005 +1001\n")
symcr_cli_test(diff_across_a_patch EXIT 1
  ARGS diff --slot-a 2 --slot-b 3 ${files}/patched.store ${files}/patched.store
  EXPECT "\n~ +copter.ticks +1003 +2001 +\\(int32 -> int64\\)\n"
         "\n\\+ +copter.geofence +\\(absent\\) +150\n")
symcr_cli_test(diff_json EXIT 1 JSON ARGS diff --json ${files}/v0.ckpt ${files}/v1.ckpt
  EXPECT "\"path\": \"copter.geofence\",[ \n]*\"change\": \"added\",[ \n]*\"b\": 150"
         "\"removed\": [1-9]")
symcr_cli_test(diff_corrupt EXIT 2 ARGS diff ${files}/v0.ckpt ${files}/corrupt.ckpt
  EXPECT "corrupt.ckpt: checksum mismatch")
symcr_cli_test(diff_truncated EXIT 2 ARGS diff ${files}/truncated.ckpt ${files}/v0.ckpt
  EXPECT "truncated")

# ---- convert (its conversions: tests/crossversion CONVERT pairs, examples/watchdog) -------------
# The fixtures hold a std::string: only the device profile's kinds convert, nothing is written.
symcr_cli_test(convert_refuses_host_kinds EXIT 2
               ARGS convert ${files}/v0.ckpt --schema ${files}/v1.schema --initial ${files}/v1.ckpt
                    -o ${files}/converted.ckpt
               EXPECT "type 'std::string' needs the build's own code")
symcr_cli_test(convert_corrupt EXIT 2
               ARGS convert ${files}/corrupt.ckpt --schema ${files}/v1.schema
                    -o ${files}/converted.ckpt
               EXPECT "checksum")
symcr_cli_test(convert_needs_output EXIT 2 ARGS convert ${files}/v0.ckpt --schema ${files}/v1.schema
               EXPECT "-o")
# With the program's keys, only a checkpoint its restore accepts as authentic converts (checked
# first: the signed fixture then meets the host-kind refusal above).
symcr_cli_test(convert_signed_with_key EXIT 2
               ARGS convert ${files}/signed.ckpt --schema ${files}/v1.schema
                    -o ${files}/converted-signed.ckpt --key-file ${files}/fixture.key --key-id 7
               EXPECT "type 'std::string' needs the build's own code"
               REJECT "MAC")
symcr_cli_test(convert_signed_other_key EXIT 1
               ARGS convert ${files}/signed.ckpt --schema ${files}/v1.schema
                    -o ${files}/converted-signed.ckpt --key-file ${files}/other.key --key-id 7
               EXPECT "MAC does not verify.*nothing written")
symcr_cli_test(convert_unsigned_with_key EXIT 1
               ARGS convert ${files}/v0.ckpt --schema ${files}/v1.schema
                    -o ${files}/converted-signed.ckpt --key-ring ${files}/keys.ring
               EXPECT "carries no MAC.*nothing written")
symcr_cli_test(convert_rolled_back_store EXIT 1
               ARGS convert ${files}/rolled-back.store --schema ${files}/v0.schema
                    -o ${files}/converted-signed.ckpt --key-ring ${files}/keys.ring
               EXPECT "RolledBack|rolled back.*nothing written")

# ---- plan -----------------------------------------------------------------------------------
symcr_cli_test(plan_same_build EXIT 0 ARGS plan ${files}/v0.ckpt --schema ${files}/v0.schema
  EXPECT "\ncopter +restored" "restore would succeed"
  REJECT "[])a-z] +(converted|dropped|kept|rejected)[ \n]")
symcr_cli_test(plan_patch EXIT 0 ARGS plan ${files}/v0.ckpt --schema ${files}/v1.schema
  EXPECT "checkpoint +.*v0.ckpt \\(sequence 0"
         "build +.*v1.schema \\(schema [0-9a-f]+, 17 types, 2 roots\\)"
         "copter.ticks +converted +int32 -> int64"
         "copter.armed_ms +dropped +\\*"
         "copter.geofence +kept"
         "copter.mission.active_index +converted +renamed from current"
         "copter.battery +converted +float32 -> float64"
         "restore would succeed"
  REJECT "[])a-z] +rejected[ \n]")
symcr_cli_test(plan_patch_strict EXIT 1 ARGS plan --strict ${files}/v0.ckpt --schema ${files}/v1.schema
  EXPECT "mode +strict" "restore would fail: Strict: strict mode: lossy restore refused")
symcr_cli_test(plan_kind_change EXIT 1 ARGS plan ${files}/v0.ckpt --schema ${files}/v1-kind-change.schema
  EXPECT "copter.home +rejected +\\*" "[1-9][0-9]* rejected")
symcr_cli_test(plan_rejected_value EXIT 1 ARGS plan ${files}/v0-weak-signal.ckpt --schema ${files}/v1.schema
  EXPECT "telemetry.rssi +rejected +\\* +-270 out of range"
         "restore would proceed with 1 rejected")
symcr_cli_test(plan_json EXIT 0 JSON ARGS plan --json ${files}/v0.ckpt --schema ${files}/v1.schema
  EXPECT "\"would_restore\": true" "\"strict\": false"
         "\"path\": \"copter.geofence\",[ \n]*\"decision\": \"kept\"")
symcr_cli_test(plan_from_store EXIT 0 ARGS plan ${files}/torn.store --schema ${files}/v1.schema
  EXPECT "torn.store slot 0 \\(sequence 5" "restore would succeed")
symcr_cli_test(plan_empty_store EXIT 2 ARGS plan ${files}/empty.store --schema ${files}/v1.schema
  EXPECT "nothing would be restored: no slot holds a restorable checkpoint")
symcr_cli_test(plan_checkpoint_as_schema EXIT 2 ARGS plan ${files}/v0.ckpt --schema ${files}/v1.ckpt
  EXPECT "a checkpoint, not a schema file")
symcr_cli_test(plan_corrupt EXIT 2 ARGS plan ${files}/corrupt.ckpt --schema ${files}/v1.schema
  EXPECT "checksum mismatch")
symcr_cli_test(plan_no_schema EXIT 2 ARGS plan ${files}/v0.ckpt
  EXPECT "must be specified at least once|Must specify|schema")

# ---- hostile files --------------------------------------------------------------------------
add_test(NAME cli_hostile_files
         COMMAND ${CMAKE_COMMAND} -DSYMCR=$<TARGET_FILE:symcr-cli>
                 -DFIXTURE=$<TARGET_FILE:symcr_cli_fixture_v0> -DSOURCE=${files}/v0.ckpt
                 -DSCHEMA=${files}/v1.schema -DWORK=${CMAKE_CURRENT_BINARY_DIR}/hostile
                 -DSTEP=11 -P ${CMAKE_CURRENT_SOURCE_DIR}/hostile_files.cmake)
set_tests_properties(cli_hostile_files PROPERTIES FIXTURES_REQUIRED symcr_cli_files)

# ---- colour: only on a terminal, and never with NO_COLOR ------------------------------------
find_program(SYMCR_SCRIPT script)  # util-linux: runs a command on a pseudo-terminal
if(SYMCR_SCRIPT)
  foreach(case colour no_colour)
    set(expect "EXPECT=${esc}\\[36m42.28${esc}\\[0m")
    set(environment "ENV=")
    if(case STREQUAL no_colour)
      set(expect "REJECT=${esc}\\[")
      set(environment "ENV=NO_COLOR=1")
    endif()
    add_test(NAME cli_tty_${case}
             COMMAND ${CMAKE_COMMAND}
                     "-DCOMMAND=${SYMCR_SCRIPT}@@-qec@@$<TARGET_FILE:symcr-cli> inspect ${files}/v0.ckpt@@/dev/null"
                     -DEXPECT_EXIT=0 "-D${expect}" "-D${environment}"
                     -P ${CMAKE_CURRENT_SOURCE_DIR}/run_cli.cmake)
    set_tests_properties(cli_tty_${case} PROPERTIES FIXTURES_REQUIRED symcr_cli_files)
  endforeach()
endif()
symcr_cli_test(version EXIT 0 ARGS --version EXPECT "symcr [0-9]+\\.[0-9]+\\.[0-9]+")

# ---- authenticated checkpoints --------------------------------------------------------------
symcr_cli_test(verify_signed_with_key EXIT 0
               ARGS verify ${files}/signed.ckpt --key-file ${files}/fixture.key --key-id 7
               EXPECT "authentication +ok +MAC verifies with key id 7")
symcr_cli_test(verify_signed_without_key EXIT 0 ARGS verify ${files}/signed.ckpt
               EXPECT "MAC with key id 7, not verified \\(no --key-file\\)")
symcr_cli_test(verify_signed_other_key EXIT 1
               ARGS verify ${files}/signed.ckpt --key-file ${files}/other.key --key-id 7
               EXPECT "MAC does not verify with key id 7")
symcr_cli_test(verify_signed_other_key_id EXIT 1
               ARGS verify ${files}/signed.ckpt --key-file ${files}/fixture.key --key-id 3
               EXPECT "key id 7, which this program does not hold")
symcr_cli_test(verify_tampered_signed EXIT 1
               ARGS verify ${files}/signed-tampered.ckpt --key-file ${files}/fixture.key --key-id 7
               EXPECT "MAC does not verify")
symcr_cli_test(verify_unsigned_with_key EXIT 1
               ARGS verify ${files}/v0.ckpt --key-file ${files}/fixture.key --key-id 7
               EXPECT "carries no MAC")
symcr_cli_test(inspect_signed EXIT 0 ARGS inspect ${files}/signed.ckpt
               EXPECT "authenticated +HMAC-SHA-256, key id 7")

# ---- the store's journal and keys: plan, inspect and verify pick the slot the program's next
# start restores (the journal applied as that start applies it, the keys' MACs checked) --------
# unconfirmed.store: a start restored 6 and stopped before confirm(): the next start restores 5.
symcr_cli_test(inspect_unconfirmed_store EXIT 0 ARGS inspect ${files}/unconfirmed.store
  EXPECT "restore_journal +restore of #6 unconfirmed. fallback depth 3\n"
         "next_start +counts the unconfirmed restore of #6 as a crash: suspect #6 \\(1 fallback\\)"
         "restore_latest +slot 0 \\(sequence 5\\)"
         "\n1 +valid +6 .*the last start restored it and stopped before Store::confirm\\(\\)"
         "\n0 +valid +5 .*<- shown" "copter.ticks += 1005\n")
symcr_cli_test(verify_unconfirmed_store EXIT 0 ARGS verify ${files}/unconfirmed.store
  EXPECT "restore_latest +slot 0 \\(sequence 5\\)" "\nvalid\n")
symcr_cli_test(plan_unconfirmed_store EXIT 0
  ARGS plan ${files}/unconfirmed.store --schema ${files}/v1.schema
  EXPECT "checkpoint +.*unconfirmed.store slot 0 \\(sequence 5,"
         "\npassed over slot 1 \\(sequence 6\\): crash-loop fallback: suspect"
         "restore would succeed")
symcr_cli_test(plan_unconfirmed_store_json EXIT 0 JSON
  ARGS plan --json ${files}/unconfirmed.store --schema ${files}/v1.schema
  EXPECT "\"slot\": 0" "\"sequence\": 5"
         "\"skipped\": \\[[ \n]*{[ \n]*\"slot\": 1,[ \n]*\"sequence\": 6,[ \n]*\"reason\": \"crash-loop")
# exhausted.store: four unconfirmed starts at depth 3 (6, 5, 4 suspect; 3 unconfirmed): the next
# start counts a fourth crash and gives up on every checkpoint.
symcr_cli_test(plan_exhausted_store EXIT 1
  ARGS plan ${files}/exhausted.store --schema ${files}/v0.schema
  EXPECT "checkpoint +.*exhausted.store \\(no checkpoint: the program's next start would restore none\\)"
         "\npassed over slot 1 \\(sequence 6\\): crash-loop fallback: given up on"
         "\npassed over slot 2 \\(sequence 3\\): crash-loop fallback: given up on"
         "restore would fail: NoValidSlot: .*nothing would be restored: the next start counts the restore of #3, never confirmed, as a crash past the fallback depth 3 and gives up on every checkpoint through #6"
  REJECT "restore would succeed" "\ncopter +restored")
symcr_cli_test(plan_exhausted_store_json EXIT 1 JSON
  ARGS plan --json ${files}/exhausted.store --schema ${files}/v0.schema
  EXPECT "\"slot\": null" "\"would_restore\": false" "\"error\": \"NoValidSlot\""
         "\"skipped\": \\[[ \n]*{[ \n]*\"slot\": 1,[ \n]*\"sequence\": 6")
symcr_cli_test(inspect_exhausted_store EXIT 2 ARGS inspect ${files}/exhausted.store
  EXPECT "restore_journal +restore of #3 unconfirmed. suspect #4 to #6 \\(3 fallbacks\\). fallback depth 3"
         "next_start +counts the unconfirmed restore of #3 as a crash, past the fallback depth: gives up on every checkpoint through #6"
         "restore_latest +none \\(nothing would be restored: "
         "error: .*exhausted.store: nothing would be restored"
  REJECT "<- shown")
symcr_cli_test(verify_exhausted_store EXIT 1 ARGS verify ${files}/exhausted.store
  EXPECT "\ninvalid: nothing would be restored: ")
# gave-up.store: the fifth such start gave up; no checkpoint saved before it is restored again.
symcr_cli_test(plan_gave_up_store EXIT 1 ARGS plan ${files}/gave-up.store --schema ${files}/v0.schema
  EXPECT "restore would fail: NoValidSlot: .*nothing would be restored: 4 checkpoints passed over by the crash-loop fallback"
  REJECT "restore would succeed")
symcr_cli_test(plan_matrix_gave_up_store EXIT 1
  ARGS plan ${files}/gave-up.store ${files}/v0.ckpt --schema ${files}/v0.schema
  EXPECT "gave-up.store +- +- +fails: NoValidSlot\n"
         "1 of 2 would restore. 1 would not, 0 unreadable"
         "\ncheckpoint +.*gave-up.store \\(no checkpoint: ")
symcr_cli_test(inspect_gave_up_store EXIT 2 ARGS inspect ${files}/gave-up.store
  EXPECT "restore_journal +nothing unconfirmed. given up through #6. fallback depth 3\n"
         "next_start +applies the journal as it is\n"
         "\n1 +valid +6 .*crash-loop fallback: given up on")
# rotated.store: sequences 1-2 signed with key id 7 (fixture.key), 3-4 with id 8 (other.key).
symcr_cli_test(verify_rotated_store_both_keys EXIT 0
  ARGS verify ${files}/rotated.store --key-file ${files}/fixture.key --key-id 7
       --key-file ${files}/other.key --key-id 8
  EXPECT "restore_latest +slot 3 \\(sequence 4\\)" "\nvalid\n" REJECT "unauthenticated")
# With the old key alone the freshness counter (signed with the new one) cannot be trusted.
symcr_cli_test(verify_rotated_store_old_key EXIT 1
  ARGS verify ${files}/rotated.store --key-file ${files}/fixture.key --key-id 7
  EXPECT "freshness +the freshness counter .*rotated.store.fresh cannot be trusted: it is signed with key id 8"
         "restore_latest +none"
         "\n3 +unauthenticated +4 .*key id 8, which this program does not hold"
         "\ninvalid: 2 damaged slot")
symcr_cli_test(verify_rotated_store_key_ring EXIT 0
  ARGS verify ${files}/rotated.store --key-ring ${files}/keys.ring
  EXPECT "freshness +fresh: the counter .*rotated.store.fresh says 4 was written"
         "restore_latest +slot 3 \\(sequence 4\\)" "\nvalid\n" REJECT "unauthenticated")
# A store copied without its counter: refused, as the program refuses it (RolledBack).
symcr_cli_test(verify_store_without_its_counter EXIT 1
  ARGS verify ${files}/no-counter.store --key-ring ${files}/keys.ring
  EXPECT "freshness +the freshness counter .*no-counter.store.fresh is missing"
         "restore_latest +none" "\ninvalid" REJECT "not checked")
symcr_cli_test(verify_bad_key_ring EXIT 2 ARGS verify ${files}/rotated.store --key-ring ${files}/bad.ring
  EXPECT "line 1 is not \"<id> <key file>\"")
symcr_cli_test(verify_rolled_back_store EXIT 1
  ARGS verify ${files}/rolled-back.store --key-file ${files}/fixture.key --key-id 7
  EXPECT "freshness +the store: rolled back: its newest authenticated checkpoint is sequence 2 .*counter says 4 was written"
         "restore_latest +none")
symcr_cli_test(verify_rolled_back_store_json EXIT 1 JSON
  ARGS verify --json ${files}/rolled-back.store --key-file ${files}/fixture.key --key-id 7
  EXPECT "\"freshness\": {[ \n]*\"rolled_back\": true")
symcr_cli_test(inspect_store_with_another_stores_counter EXIT 2
  ARGS inspect ${files}/rolled-back.store --key-ring ${files}/keys.ring
       --counter ${files}/rotated.store.fresh
  EXPECT "freshness +the freshness counter .* cannot be trusted: it is the counter of another store")
symcr_cli_test(plan_rolled_back_store EXIT 1
  ARGS plan ${files}/rolled-back.store --schema ${files}/v0.schema --key-ring ${files}/keys.ring
  EXPECT "restore would fail: RolledBack: .*counter says 4 was written")
symcr_cli_test(inspect_rotated_store_new_key EXIT 0
  ARGS inspect ${files}/rotated.store --key-id 8 --key-file ${files}/other.key
  EXPECT "restore_latest +slot 3 \\(sequence 4\\)" "\n0 +unauthenticated +1 .*key id 7"
         "copter.ticks += 1002\n")
symcr_cli_test(plan_rotated_store_old_key EXIT 1
  ARGS plan ${files}/rotated.store --schema ${files}/v0.schema --key-file ${files}/fixture.key
       --key-id 7
  EXPECT "restore would fail: RolledBack: .*nothing would be restored: the freshness counter .*rotated.store.fresh cannot be trusted"
  REJECT "restore would succeed")
symcr_cli_test(plan_rotated_store_no_keys EXIT 0
  ARGS plan ${files}/rotated.store --schema ${files}/v0.schema
  EXPECT "rotated.store slot 3 \\(sequence 4," "restore would succeed" REJECT "passed over")
symcr_cli_test(plan_rotated_store_wrong_key EXIT 1
  ARGS plan ${files}/rotated.store --schema ${files}/v0.schema --key-file ${files}/other.key
       --key-id 7
  EXPECT "restore would fail: NoValidSlot: .*nothing would be restored: 4 checkpoints unauthenticated with the keys given")
symcr_cli_test(plan_unsigned_with_key EXIT 1
  ARGS plan ${files}/v0.ckpt --schema ${files}/v0.schema --key-file ${files}/fixture.key --key-id 7
  EXPECT "restore would fail: Unauthenticated: the checkpoint carries no MAC")
symcr_cli_test(key_ids_do_not_pair EXIT 2
  ARGS verify ${files}/rotated.store --key-file ${files}/fixture.key --key-file ${files}/other.key
       --key-id 7
  EXPECT "2 --key-file and 1 --key-id: give each key file its id")
symcr_cli_test(key_file_missing EXIT 2
  ARGS plan ${files}/rotated.store --schema ${files}/v0.schema --key-file ${files}/no-such.key
  EXPECT "--key-file: cannot open .*no-such.key")
symcr_cli_test(key_ids_repeated EXIT 2
  ARGS inspect ${files}/rotated.store --key-file ${files}/fixture.key --key-id 7
       --key-file ${files}/other.key --key-id 7
  EXPECT "--key-file: two checkpoint keys have id 7")
