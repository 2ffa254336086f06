# scenes.jq: the scenes of a Gradescope-style results.json (grade --self --gradescope FILE), for
# the converters of platforms/ (github-classroom, prairielearn, codegrade): a jq module.
#
# Usage: jq -L platforms 'include "scenes"; raytra_scenes | ...' results.json
#
# raytra_scenes reads the tests of results.json, a test a scene (those with a max_score: the
# note "Scenes not shown" has none), into objects:
#   name     the scene's name (the test's name without " (SCENE FILE)")
#   file     the scene's file, as the test's name gives it in parentheses
#   pass     true when it passed
#   score    the points it earned, max the points it is worth (grading.conf's, scaled)
#   visible  true when grading.conf shows it at once ("visible"), false for a scene shown
#            later or never (after_due_date, after_published, hidden)
#   verdict  PASS, FAIL, WRONG SIZE, LINK, UNREADABLE, MISSING, ERROR, CRASHED, TIMEOUT,
#            OUT OF MEMORY or BUILD FAILED: the first words of its output
#   reason   the rest of the output's first line, without its final dot
#   error    true for a verdict of the ERROR column (the program, or its build, failed)
#   seconds  how long its program ran (the output's "Ran in S s."), 0 for an image
#   output   the output as it is: the verdict, figures, what to do, the command line
# raytra_fold(all): the scenes, but when all is false each scene not visible is left out and
# one entry stands for them all, named "Scenes not shown", with their points, verdict PASS
# when they all pass (FAIL otherwise) and an output that counts them and names none: the
# platforms of this folder show every test at once, and a scene whose visibility says
# "later" or "never" keeps its name and output to itself.
# raytra_part: the part, as the summary's first line names it ("" when it names none).
# raytra_summary: "Part P: K of N scenes pass: X of Y points." over every scene.
# raytra_details: the summary's text after its first paragraph (what went wrong before any
# scene, make's last output, the limits, the sandbox); the whole output when it has no
# "Part" line (run_autograder's own results.json, written when the grading failed).

def raytra_error_verdicts: ["ERROR", "CRASHED", "TIMEOUT", "OUT OF MEMORY", "BUILD FAILED"];
def raytra_verdicts:
    ["PASS", "FAIL", "WRONG SIZE", "LINK", "UNREADABLE", "MISSING"] + raytra_error_verdicts;

# Points as a short number: at most 4 decimals, no trailing zeros.
def raytra_points: (. * 10000 | round) / 10000;

def raytra_scenes:
    [.tests[]? | select(has("max_score")) |
        (.output // "") as $out |
        ($out | split("\n")[0]) as $first |
        ($first | capture("^(?<v>[A-Z][A-Z ]*[A-Z]): (?<r>.*)$") //
            {v: "", r: $first}) as $head |
        (if ($head.v | IN(raytra_verdicts[])) then $head.v
         elif .status == "passed" then "PASS" else "FAIL" end) as $verdict |
        {
            name: ((.name // "") | (capture("^(?<n>.*) \\([^()]*\\)$").n // .)),
            file: ((.name // "") | (capture(" \\((?<f>[^()]*)\\)$").f // "")),
            pass: (.status == "passed"),
            score: (.score // 0),
            max: .max_score,
            visible: ((.visibility // "visible") == "visible"),
            verdict: $verdict,
            reason: ($head.r | sub("\\.$"; "")),
            error: ($verdict | IN(raytra_error_verdicts[])),
            seconds: (($out | capture("Ran in (?<s>[0-9.]+) s").s // "0") | tonumber),
            output: $out
        }];

def raytra_fold(all):
    if all then .
    else
        map(select(.visible)) +
        (map(select(.visible | not)) |
            if length == 0 then []
            else (map(select(.pass)) | length) as $passed |
                [{
                    name: "Scenes not shown",
                    file: "",
                    pass: ($passed == length),
                    score: (map(.score) | add),
                    max: (map(.max) | add),
                    visible: false,
                    verdict: (if $passed == length then "PASS" else "FAIL" end),
                    reason: "\($passed) of \(length) scenes not shown here pass",
                    error: false,
                    seconds: (map(.seconds) | add),
                    output: ("\($passed) of \(length) scene\(if length == 1 then "" else "s" end) "
                        + "of your instructor's, not shown here, pass: "
                        + "\(map(.score) | add | raytra_points) of "
                        + "\(map(.max) | add | raytra_points) points.\n")
                }]
            end)
    end;

def raytra_part: (.output // "") | capture("^Part (?<p>[^:\n]*):").p // "";

def raytra_summary:
    . as $results |
    raytra_scenes as $scenes |
    raytra_part as $part |
    ($scenes | map(select(.pass)) | length) as $passed |
    if ($scenes | length) == 0 then
        (($results.output // "") | split("\n")[0])
    else
        "\(if $part != "" then "Part \($part): " else "" end)\($passed) of \($scenes | length) "
        + "scene\(if ($scenes | length) == 1 then "" else "s" end) pass: "
        + "\($scenes | map(.score) | add | raytra_points) of "
        + "\($scenes | map(.max) | add | raytra_points) points."
    end;

def raytra_details:
    (.output // "") as $out |
    if ($out | test("^Part [^:\n]*:")) then
        ($out | index("\n\n")) as $cut |
        if $cut then $out[$cut + 2:] else "" end
    else $out end;
