#!/bin/sh
# imgdiff.sh: tests imgdiff on small PFM images made here, byte by byte, and on its heat maps.
#
# Usage: compare/tests/imgdiff.sh IMGDIFF   (make -C compare test runs it)
#
# The images are 4 x 3 PFMs, grey (0.25, 0.5, 1) but for a few pixels, written with
# printf so that every value is known exactly. Exit status 0 when every check passes.
set -u
[ $# -eq 1 ] || { echo "usage: $0 IMGDIFF" >&2; exit 2; }
imgdiff=$1
case $imgdiff in /*) ;; *) imgdiff=$(pwd)/$imgdiff ;; esac
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT TERM
cd "$tmp" || exit 2

checks=0
failures=0
command=""

# Reports a failed check.
fail() {
    failures=$((failures + 1))
    echo "FAIL: $command: $1"
    sed 's/^/    | /' out.txt err.txt
}

# Prints the four bytes of a float, little-endian; only the values the tests use.
f32() {
    case $1 in
    0) printf '\000\000\000\000' ;;
    0.0078125) printf '\000\000\000\074' ;; # 2^-7 = 1.99/255
    0.015625) printf '\000\000\200\074' ;;  # 2^-6 = 3.98/255
    0.25) printf '\000\000\200\076' ;;
    0.5) printf '\000\000\000\077' ;;
    0.5078125) printf '\000\000\002\077' ;; # 0.5 + 2^-7
    0.75) printf '\000\000\100\077' ;;
    1) printf '\000\000\200\077' ;;
    0.21484375) printf '\000\000\134\076' ;;
    0.5234375) printf '\000\000\006\077' ;;
    7) printf '\000\000\340\100' ;;
    -1) printf '\000\000\200\277' ;;
    nan) printf '\000\000\300\177' ;;
    inf) printf '\000\000\200\177' ;;
    *) echo "imgdiff.sh: no bytes for $1" >&2; exit 2 ;;
    esac
}

# Writes a W x H PFM: every pixel BASE (R,G,B) but those given as x,y=R,G,B, y from
# the top. PFM stores the bottom row first. R,G,B is split at its commas by the shell
# itself (IFS), without a process a pixel.
blank=$IFS
pfm() {
    file=$1 w=$2 h=$3 base=$4
    shift 4
    {
        printf 'PF\n%s %s\n-1.0\n' "$w" "$h"
        y=$((h - 1))
        while [ $y -ge 0 ]; do
            x=0
            while [ $x -lt "$w" ]; do
                rgb=$base
                for p in "$@"; do
                    case $p in "$x,$y="*) rgb=${p#*=} ;; esac
                done
                IFS=,
                for v in $rgb; do f32 "$v"; done
                IFS=$blank
                x=$((x + 1))
            done
            y=$((y - 1))
        done
    } >"$file"
}

# Runs imgdiff with the arguments after the exit status it should give.
run() {
    expected=$1
    shift
    command="imgdiff $*"
    checks=$((checks + 1))
    "$imgdiff" "$@" >out.txt 2>err.txt
    status=$?
    [ "$status" -eq "$expected" ] || fail "exit status $status, expected $expected"
}

# Checks that the last run printed the line (on stdout or stderr).
has() {
    grep -qxF -- "$1" out.txt err.txt || fail "no line '$1'"
}

# Checks that the last run printed text somewhere (on stdout or stderr).
says() {
    grep -qF -- "$1" out.txt err.txt || fail "no '$1'"
}

grey=0.25,0.5,1
pfm a.pfm 4 3 $grey
pfm same.pfm 4 3 $grey
pfm one.pfm 4 3 $grey 2,1=0.75,0.5,1
pfm two.pfm 4 3 $grey 2,1=0.75,0.5,1 0,0=0.5,0.5,1
pfm small.pfm 4 3 $grey 1,2=0.25,0.5078125,1
pfm step2.pfm 4 3 0,0,0 3,0=0,0,0.0078125
pfm step4.pfm 4 3 0,0,0 3,0=0,0,0.015625
pfm black.pfm 4 3 0,0,0
pfm tall.pfm 3 4 $grey

# Identical images.
run 0 a.pfm same.pfm
has "size: 4 x 3 pixels"
has "largest difference (R, G, B): 0, 0, 0 /255"
has "PSNR: inf (equal)"
has "differing pixels: 0 (0%) of 12 differ by more than 2/255"
has "PASS: the images are identical"

# One pixel off by 0.5 in red: 1 of 12 pixels is 8.3%, more than the 0.1% allowed.
# Mean = 0.5 / 36 channels = 0.01389 (3.54/255); RMSE = sqrt(0.25 / 36) = 1/12; PSNR = 20 log10 12.
run 1 a.pfm one.pfm
has "largest difference (R, G, B): 128, 0, 0 /255"
has "mean absolute difference: 3.54 /255"
has "RMSE: 0.08333"
has "PSNR: 21.58 dB"
has "differing pixels: 1 (8.33%) of 12 differ by more than 2/255"
has "differing region: (2,1)-(2,1), y from the top"
has "FAIL: 8.33% of the pixels differ by more than 2/255, more than the 0.1% allowed"
run 1 --allow 0 one.pfm a.pfm
run 0 --allow 0.1 a.pfm one.pfm
has "PASS: 8.33% of the pixels differ by more than 2/255, within the 10% allowed"
run 0 --allow=1/12 a.pfm one.pfm

# --cover: a pixel differs when A is drawn there (a channel above the threshold) and B is
# black; B drawn where A is black, or drawn otherwise, is no difference. step4.pfm is drawn
# at (3,0) only (3.98/255), step2.pfm nowhere (1.99/255 is within 2/255).
run 0 --cover --allow 0 black.pfm a.pfm
has "PASS: 0% of the pixels are drawn in black.pfm (A) and not in a.pfm (B: black, at most 2/255), within the 0% allowed"
run 0 --cover --allow 0 a.pfm one.pfm
run 1 --cover --allow 0 step4.pfm step2.pfm
has "FAIL: 8.33% of the pixels are drawn in step4.pfm (A) and not in step2.pfm (B: black, at most 2/255), more than the 0% allowed"
run 1 --cover --machine a.pfm black.pfm
has "differing 12 12"
has "box 0 0 3 2"
run 0 --cover --allow 0 step2.pfm black.pfm

# Two pixels: the box spans both.
run 1 a.pfm two.pfm
has "differing pixels: 2 (16.7%) of 12 differ by more than 2/255"
has "differing region: (0,0)-(2,1), y from the top"

# The threshold: 2^-7 = 1.99/255 is within 2/255, 2^-6 = 3.98/255 is not; a fraction
# and a decimal say the same.
run 0 --allow 0 a.pfm small.pfm
has "PASS: no pixel differs by more than 2/255"
run 0 --allow 0 black.pfm step2.pfm
run 1 --allow 0 black.pfm step4.pfm
has "differing region: (3,0)-(3,0), y from the top"
run 1 --allow 0 --threshold 1/255 black.pfm step2.pfm
has "differing pixels: 1 (8.33%) of 12 differ by more than 1/255"
run 0 --allow 0 --threshold 0.0078125 black.pfm step2.pfm
run 0 --allow 0 --threshold=4/255 black.pfm step4.pfm

# Quiet: the verdict alone.
run 1 -q a.pfm one.pfm
lines=$(($(wc -l <out.txt)))
if [ "$lines" -ne 1 ] || [ -s err.txt ]; then fail "more than the verdict"; fi
has "FAIL: 8.33% of the pixels differ by more than 2/255, more than the 0.1% allowed"

# Machine-readable figures, for grader/grade: every value, with enough digits.
run 1 --machine --diff heatm.png a.pfm two.pfm
has "threshold 0.00784313725"
has "allow 0.001"
has "size 4 3"
has "max 0.5 0 0"
has "mean 0.0208333333"
has "rmse 0.0931694991"
has "differing 2 12"
has "box 0 0 2 1"
has "heat_scale 0.5"
has "verdict FAIL"
lines=$(($(wc -l <out.txt)))
[ "$lines" -eq 11 ] || fail "11 lines expected, got $lines"
run 0 --machine a.pfm same.pfm
has "psnr inf"
has "differing 0 12"
has "verdict PASS"
grep -q '^box\|^heat_scale' out.txt && fail "a box or a heat scale for equal images"
run 2 --machine a.pfm tall.pfm
has "sizes 4 3 3 4"
has "imgdiff: sizes differ: a.pfm is 4 x 3, tall.pfm is 3 x 4"

# Trouble: sizes, missing and unreadable files.
run 2 a.pfm tall.pfm
has "imgdiff: sizes differ: a.pfm is 4 x 3, tall.pfm is 3 x 4"
run 2 a.pfm missing.png
has "imgdiff: cannot read 'missing.png': No such file or directory"
printf 'hello\n' >text.png
run 2 text.png a.pfm
has "imgdiff: cannot read 'text.png': not a PNG, PFM or OpenEXR image"
dd if=a.pfm of=cut.pfm bs=1 count=30 2>/dev/null
run 2 a.pfm cut.pfm
has "imgdiff: cannot read 'cut.pfm': truncated: expected 144 bytes of pixels, found 18"

# The heat map of two.pfm: (2,1) differs most (0.5), so it is white; (0,0) differs
# by 0.25, half way up the ramp of five colours, so red; equal pixels are black.
run 1 --diff heat.png a.pfm two.pfm
has "heat map: black where equal, white at 128/255, written to heat.png"
pfm expected.pfm 4 3 0,0,0 2,1=1,1,1 0,0=1,0,0
run 0 --threshold 0 --allow 0 heat.png expected.pfm
has "note: expected.pfm holds linear values: compared as raytra would write them to a PNG (clamped to [0, 1], sRGB, 8 bits)"
has "PASS: the images are identical"
# With --scale 1, 0.5 is red and 0.25 purple (0.5, 0, 0.75), exactly in a PFM.
run 1 --diff heat2.pfm --scale 1 a.pfm two.pfm
has "heat map: black where equal, white at 255/255, written to heat2.pfm"
pfm expected2.pfm 4 3 0,0,0 2,1=1,0,0 0,0=0.5,0,0.75
run 0 --threshold 0 --allow 0 heat2.pfm expected2.pfm
# A PNG against a linear image: the linear one is clamped, sRGB-encoded and rounded to
# 8 bits first. The same map as a PNG stores red (1, 0, 0) and purple as 128/255 and
# 191/255; 7 and -1 clamp to 1 and 0; 0.21484375 encodes to 127.7/255 and 0.5234375 to
# 191.4/255.
run 1 --diff heat2.png --scale 1 a.pfm two.pfm
pfm encoded.pfm 4 3 0,0,0 2,1=7,-1,0 0,0=0.21484375,0,0.5234375
run 0 --threshold 0 --allow 0 heat2.png encoded.pfm
has "note: encoded.pfm holds linear values: compared as raytra would write them to a PNG (clamped to [0, 1], sRGB, 8 bits)"
has "PASS: the images are identical"
# Identical images make an all-black map, and a PNG compared with itself is identical.
run 0 --diff heat3.png a.pfm same.pfm
run 0 --threshold 0 --allow 0 heat3.png black.pfm
run 0 heat.png heat.png
has "PASS: the images are identical"
# A heat map that cannot be written is refused before any work.
run 2 --diff heat.jpg a.pfm two.pfm
has "imgdiff: cannot write 'heat.jpg': unknown image format (use .png or .pfm)"
run 2 --diff nowhere/heat.png a.pfm two.pfm
has "imgdiff: cannot write 'nowhere/heat.png': folder 'nowhere' does not exist"
run 2 --diff a.pfm a.pfm two.pfm
says "would overwrite"
# However the input is spelt: ./, an absolute path, d/../, a symbolic or a hard link.
mkdir d
cp a.pfm keep.pfm
ln -s a.pfm soft.pfm
ln a.pfm hard.pfm
for spelling in ./a.pfm "$tmp/a.pfm" d/../a.pfm soft.pfm hard.pfm; do
    run 2 --diff "$spelling" a.pfm two.pfm
    says "would overwrite a.pfm, an image being compared"
done
run 0 --threshold 0 --allow 0 a.pfm keep.pfm

# Thumbnails, for grader/grade's report: an image no larger than 320 pixels a side is its
# own thumbnail, and so is its heat map; a larger one is shrunk by a whole factor, each
# pixel its block's mean, or for the heat map its brightest, so that one pixel stays.
run 1 --thumb thumb.pfm --diff-thumb heat-thumb.pfm a.pfm two.pfm
run 0 --threshold 0 --allow 0 thumb.pfm two.pfm
run 0 --threshold 0 --allow 0 heat-thumb.pfm expected.pfm
pfm wide-black.pfm 321 1 0,0,0
pfm wide-dot.pfm 321 1 0,0,0 0,0=1,1,1
run 1 --thumb thumb2.pfm --diff-thumb heat-thumb2.pfm wide-black.pfm wide-dot.pfm
pfm expected-thumb.pfm 161 1 0,0,0 0,0=0.5,0.5,0.5
run 0 --threshold 0 --allow 0 thumb2.pfm expected-thumb.pfm
pfm expected-peak.pfm 161 1 0,0,0 0,0=1,1,1
run 0 --threshold 0 --allow 0 heat-thumb2.pfm expected-peak.pfm
# An image of another size is still shown (but not a bomb, below); a thumbnail may not
# overwrite an input either.
run 2 --thumb thumb3.pfm a.pfm tall.pfm
run 0 --threshold 0 --allow 0 thumb3.pfm tall.pfm
run 2 --thumb hard.pfm a.pfm two.pfm
says "would overwrite a.pfm, an image being compared"

# Non-finite pixels are never equal, not even to the same NaN or infinity.
pfm nan.pfm 4 3 $grey 1,1=nan,0.5,1
pfm inf.pfm 4 3 $grey 3,2=0.25,inf,1
for f in nan.pfm inf.pfm; do
    command="imgdiff $f $f"
    checks=$((checks + 1))
    "$imgdiff" "$f" "$f" >out.txt 2>err.txt
    status=$?
    [ "$status" -ne 0 ] || fail "two images with a non-finite pixel called a match"
    [ "$status" -ne 1 ] || grep -qxF "FAIL: 1 pixel is not finite (NaN or infinite)" out.txt ||
        fail "no line on the non-finite pixel"
done

# Nothing blocks on a FIFO, nor decodes an image whose header already says the sizes
# differ or that it is too large: a PNG header of 8192 x 8192 16-bit pixels, no pixels.
mkfifo fifo.png
run 2 a.pfm fifo.png
has "imgdiff: cannot read 'fifo.png': not a regular file (a FIFO)"
png_header() {
    printf '\211PNG\r\n\032\n\000\000\000\015IHDR'
    printf "$1"
    printf '\020\002\000\000\000\000\000\000\000'
}
png_header '\000\000\040\000\000\000\040\000' >bomb.png
run 2 a.pfm bomb.png
has "imgdiff: sizes differ: a.pfm is 4 x 3, bomb.png is 8192 x 8192"
run 2 --machine a.pfm bomb.png
has "sizes 4 3 8192 8192"
run 2 --thumb thumb4.pfm a.pfm bomb.png
[ ! -e thumb4.pfm ] || fail "a thumbnail of an image whose header says 8192 x 8192"
png_header '\000\001\000\000\000\000\000\001' >wide.png
run 2 wide.png wide.png
says "its header gives a size of 65536 x 1 pixels, beyond"

# The command line.
run 0 --help
says "Usage: imgdiff [options] A B"
says "(default 2/255)"
says "(default 0.001)"
run 2 a.pfm
has "imgdiff: give two images to compare (imgdiff --help shows how)"
run 2 a.pfm same.pfm one.pfm
has "imgdiff: unexpected argument 'one.pfm': give two images"
run 2 --frobnicate a.pfm same.pfm
has "imgdiff: unknown option '--frobnicate' (imgdiff --help lists them)"
run 2 --threshold abc a.pfm same.pfm
has "imgdiff: --threshold takes a number from 0 up, or a fraction such as 2/255, got 'abc'"
run 2 --threshold 2/0 a.pfm same.pfm
run 2 --threshold -1 a.pfm same.pfm
run 2 --allow 2 a.pfm same.pfm
has "imgdiff: --allow takes a fraction from 0 to 1, got '2'"
run 2 --scale 0 a.pfm same.pfm
run 2 a.pfm same.pfm --threshold
has "imgdiff: --threshold needs a value"
run 0 -- a.pfm same.pfm

if [ $failures -eq 0 ]; then
    echo "imgdiff.sh: all $checks runs of imgdiff passed their checks"
else
    echo "imgdiff.sh: $failures failed checks in $checks runs of imgdiff"
    exit 1
fi
