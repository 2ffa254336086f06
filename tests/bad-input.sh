#!/bin/sh
# bad-input.sh: raytra on every kind of broken input: the exit status and message each must give.
#
# Usage: tests/bad-input.sh RAYTRA
#
# Runs RAYTRA on each case of tests/bad-input/cases.txt (see its header) and checks the
# exit status, that standard error holds the expected message, and that an image was
# written exactly when raytra succeeded (a file that was already at the output's name,
# such as the scene itself, must be left byte for byte as it was). Cases named @NAME are made here at run time.
# Cases that need permissions to matter (an unreadable file, a read-only folder) are
# skipped, saying so, when they do not (as root).
set -u
[ $# -eq 1 ] || { echo "usage: $0 RAYTRA" >&2; exit 2; }
raytra=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
here=$(cd "$(dirname "$0")/bad-input" && pwd)
tmp=$(mktemp -d /tmp/raytra-bad-input.XXXXXX)
trap 'chmod -R u+rwx "$tmp"; rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM

SCENE='c 0 0 0  0 0 -1  35 35 25  32 24
m 0.8 0.1 0.1  0.5 0.5 0.5  50  0 0 0
s 0 0 -50 10'

# Makes case $1 in the current (empty) folder and sets scene and output ("-" for none: the
# default name), and skip to the reason when the case cannot be made to matter here.
make_case() {
    scene=scene.scn output=out.png skip=""
    case $1 in
    @long-line.scn)
        scene=long-line.scn
        { echo "/ long-line.scn: line 2 is 10 MB long"; printf '/'
          head -c 10485760 /dev/zero | tr '\0' x; printf '\n%s\n' "$SCENE"; } >"$scene" ;;
    @directory.scn) scene=directory.scn; mkdir "$scene" ;;
    @missing.scn) scene=missing.scn ;;
    @unreadable.scn)
        scene=unreadable.scn
        printf '%s\n' "$SCENE" >"$scene"
        chmod 000 "$scene"
        [ -r "$scene" ] && skip="permissions are not enforced (running as root)" ;;
    @unreadable-mesh.scn)
        printf '%s\nw unreadable.obj\n' "$SCENE" >"$scene"
        printf 'v 0 0 -50\nv 10 0 -50\nv 0 10 -50\nf 1 2 3\n' >unreadable.obj
        chmod 000 unreadable.obj
        [ -r unreadable.obj ] && skip="permissions are not enforced (running as root)" ;;
    @output-missing-folder) output=no-such-folder/out.png ;;
    @output-read-only-folder)
        output=read-only/out.png
        mkdir read-only
        chmod 555 read-only
        [ -w read-only ] && skip="permissions are not enforced (running as root)" ;;
    @output-is-a-folder) output=folder.png; mkdir folder.png ;;
    @output-extension) output=out.jpg ;;
    @dev-zero.scn) scene=/dev/zero ;;
    @mesh-dev-zero.scn) printf '%s\nw /dev/zero\n' "$SCENE" >"$scene" ;;
    @mesh-fifo.scn)
        printf '%s\nw fifo.obj\n' "$SCENE" >"$scene"
        mkfifo fifo.obj ;;
    @output-is-scene) scene=scene.png output=scene.png; printf '%s\n' "$SCENE" >"$scene" ;;
    @output-default-is-scene) scene=scene.png output=-; printf '%s\n' "$SCENE" >"$scene" ;;
    @output-links-to-scene) output=link.png; printf '%s\n' "$SCENE" >"$scene"; ln -s "$scene" link.png ;;
    @output-is-mesh)
        output=mesh.png
        printf '%s\nw mesh.obj\n' "$SCENE" >"$scene"
        printf 'v 0 0 -50\nv 10 0 -50\nv 0 10 -50\nf 1 2 3\n' >mesh.obj
        ln mesh.obj mesh.png ;;
    *) skip="no such generated case in tests/bad-input.sh" ;;
    esac
    [ "$scene" = scene.scn ] && [ ! -e scene.scn ] && printf '%s\n' "$SCENE" >scene.scn
    printf '%s\n%s\n%s\n' "$scene" "$output" "$skip"
}

passed=0 failed=0 skipped=0
while read -r name status message; do
    case $name in '' | '#'*) continue ;; esac
    dir=$tmp/case
    chmod -R u+rwx "$dir" 2>/dev/null
    rm -rf "$dir"
    mkdir "$dir"
    if [ "${name#@}" != "$name" ]; then
        (cd "$dir" && make_case "$name") >"$tmp/names"
        skip=$(sed -n 3p "$tmp/names")
        if [ -n "$skip" ]; then
            echo "skip $name: $skip"
            skipped=$((skipped + 1))
            continue
        fi
        scene=$(sed -n 1p "$tmp/names") output=$(sed -n 2p "$tmp/names")
        if [ "$output" = - ]; then
            image=$dir/$(basename "${scene%.*}").png
            set -- "$scene"
        else
            image=$dir/$output
            set -- "$scene" "$output"
        fi
        before=""
        [ -f "$image" ] && before=$(cksum <"$image")
        (cd "$dir" && "$raytra" -q -j 1 "$@") 2>"$tmp/err"
        got=$?
    else
        image=$dir/out.png before=""
        (cd "$here" && "$raytra" -q -j 1 "$name" "$image") 2>"$tmp/err"
        got=$?
    fi
    problem=""
    if [ "$got" -ne "$status" ]; then
        problem="exit status $got, expected $status"
    elif [ "$message" = - ]; then
        grep -v '^raytra: note: ' "$tmp/err" >"$tmp/rest"
        [ -s "$tmp/rest" ] && problem="expected no message"
    elif ! grep -qF -e "$message" "$tmp/err"; then
        problem="expected the message: $message"
    fi
    if [ -z "$problem" ] && [ "$status" -eq 0 ] && [ ! -f "$image" ]; then
        problem="no image written"
    elif [ -z "$problem" ] && [ "$status" -ne 0 ] && [ -n "$before" ]; then
        [ -f "$image" ] && [ "$(cksum <"$image")" = "$before" ] ||
            problem="the file at the output's name was changed although raytra failed"
    elif [ -z "$problem" ] && [ "$status" -ne 0 ] && [ -f "$image" ]; then
        problem="an image was written although raytra failed"
    fi
    if [ -n "$problem" ]; then
        echo "FAIL $name: $problem; standard error was:"
        sed 's/^/    /' "$tmp/err"
        failed=$((failed + 1))
    else
        passed=$((passed + 1))
    fi
done <"$here/cases.txt"
echo "bad-input: $passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
