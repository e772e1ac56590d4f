# Sourced by the CLI tests written in shell: fail and expect.
# fail TEXT: says why on stderr (and the file FAIL_LOG names, when set and
# there), then exits 1.
fail() {
  echo "FAIL: $*" >&2
  if [ -n "${FAIL_LOG:-}" ] && [ -f "$FAIL_LOG" ]; then cat "$FAIL_LOG" >&2; fi
  exit 1
}
# expect CODE TEXT COMMAND...: exit code CODE and TEXT somewhere in the output.
expect() {
  local code=$1 text=$2 out got
  shift 2
  set +e
  out=$("$@" 2>&1)
  got=$?
  set -e
  [ "$got" -eq "$code" ] || fail "$* exited $got, expected $code: $out"
  grep -qF -- "$text" <<<"$out" || fail "$* output lacks '$text': $out"
}
