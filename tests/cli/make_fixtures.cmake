# Produces the CLI tests' files in DIR with the fixture programs V0, V1 and V1K (v1 with a
# kind change), then damaged copies.
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code)
  if(NOT code EQUAL 0)
    string(REPLACE ";" " " shown "${ARGN}")
    message(FATAL_ERROR "fixture step failed (${code}): ${shown}")
  endif()
endfunction()
run(${V0} checkpoint ${DIR}/v0.ckpt 1)
run(${V0} checkpoint ${DIR}/v0-seed2.ckpt 2)
run(${V0} checkpoint ${DIR}/v0-weak-signal.ckpt 10)
run(${V1} checkpoint ${DIR}/v1.ckpt 1)
# Authenticated with key id 7, bytes "fixture-key"; and a copy changed and resealed (CRC only).
run(${V0} signed ${DIR}/signed.ckpt 1)
file(WRITE ${DIR}/fixture.key "fixture-key")
file(WRITE ${DIR}/other.key "another-key")
file(COPY_FILE ${DIR}/signed.ckpt ${DIR}/signed-tampered.ckpt)
run(${V0} flip-resign ${DIR}/signed-tampered.ckpt 100)
run(${V0} schema ${DIR}/v0.schema)
run(${V1} schema ${DIR}/v1.schema)
run(${V1K} schema ${DIR}/v1-kind-change.schema)
# Six saves into four slots: slots hold sequences 5, 6, 3, 4; the newest is slot 1.
run(${V0} store ${DIR}/v0.store 6)
run(${V0} store ${DIR}/torn.store 6)
run(${V0} flip-newest-slot ${DIR}/torn.store)
run(${V0} store ${DIR}/empty.store 0)
# Two starts that restored and crashed: the second passed over 6 and restored 5, unconfirmed.
run(${V0} store ${DIR}/crashed.store 6)
run(${V0} restore-unconfirmed ${DIR}/crashed.store 2)
# One start that restored 6 and stopped before confirm(): the next start passes over 6.
run(${V0} store ${DIR}/unconfirmed.store 6)
run(${V0} restore-unconfirmed ${DIR}/unconfirmed.store 1)
# Four such starts (depth 3): 6, 5, 4 suspect, 3 unconfirmed; the next start gives up.
run(${V0} store ${DIR}/exhausted.store 6)
run(${V0} restore-unconfirmed ${DIR}/exhausted.store 4)
# Five: the fifth gave up on every checkpoint; none is restored again.
run(${V0} store ${DIR}/gave-up.store 6)
run(${V0} restore-unconfirmed ${DIR}/gave-up.store 5)
# Sequences 1-2 signed with key id 7, 3-4 with id 8 (keys: fixture.key, other.key).
run(${V0} rotated-store ${DIR}/rotated.store)
# An authenticated store (key id 7) copied back after two more saves: older than its counter.
run(${V0} signed-store ${DIR}/rolled-back.store 2)
file(COPY_FILE ${DIR}/rolled-back.store ${DIR}/rolled-back.old)
run(${V0} signed-store ${DIR}/rolled-back.store 2)
file(COPY_FILE ${DIR}/rolled-back.old ${DIR}/rolled-back.store)
# The rotated store copied without its freshness counter: a program refuses it.
file(COPY_FILE ${DIR}/rotated.store ${DIR}/no-counter.store)
# The program's keys as a key ring file: both keys of the rotation.
file(WRITE ${DIR}/keys.ring "# id, then the key's file (relative to this file)\n7 fixture.key\n8 other.key\n")
file(WRITE ${DIR}/bad.ring "7fixture.key\n")
# A store across a patch: v0 saved sequences 1-3 (schema area 0), then v1 saved 4 (area 1).
run(${V0} store ${DIR}/patched.store 3)
run(${V1} store-more ${DIR}/patched.store 1)
file(COPY_FILE ${DIR}/v0.ckpt ${DIR}/corrupt.ckpt)
run(${V0} flip ${DIR}/corrupt.ckpt 200)
file(COPY_FILE ${DIR}/v0.ckpt ${DIR}/truncated.ckpt)
run(${V0} truncate ${DIR}/truncated.ckpt 100)
file(WRITE ${DIR}/not-a-checkpoint.txt "hello, world\n")
file(CREATE_LINK v0.ckpt ${DIR}/latest.ckpt SYMBOLIC)
file(CREATE_LINK v0.store ${DIR}/latest.store SYMBOLIC)
