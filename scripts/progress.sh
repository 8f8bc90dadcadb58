# Sourced by setup-env.sh (so by study.sh and test.sh): one line of progress, and a long step's
# output reduced to its progress lines, in full when it fails.

# One line of progress on stderr, named after the script that sourced this one.
say() { echo "$(basename "$0"): $*" >&2; }

# run_step AWK_PROGRAM COMMAND...: run COMMAND with its output in a log, print what AWK_PROGRAM
# picks from it as it comes (indented, on stderr); on failure the log's last lines and the command.
run_step() {
    local program="$1" log status
    shift
    log="$(mktemp -t pendulum-step-XXXXXX.log)"
    # the command's own exit status, whatever the caller's pipefail and errexit
    { "$@" 2>&1 && echo 0 > "$log.status" || echo $? > "$log.status"; } | tee "$log" | awk "$program" | sed -u 's/^/    /' >&2 || true
    status="$(cat "$log.status")"
    if [ "$status" != 0 ]; then
        tail -n 30 "$log" >&2
        say "failed: $* (the last lines of its output are above)"
    fi
    rm -f "$log" "$log.status"
    [ "$status" = 0 ]
}

# The awk program that picks CMake's stages from a build's output: each step with a comment (a zig
# cross-build per platform, packing an FMU, the reference result) and each target done, with the
# percentage; not every object file.
CMAKE_STAGES='/^\[ *[0-9]+%\]/ && !/Building C object|Linking C / { print; fflush() }'
