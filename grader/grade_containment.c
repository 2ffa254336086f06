/* grade_containment.c: --sandbox's choice: bubblewrap's namespaces where they work here, or the fallback. */
#include "grade_containment.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "grade_base.h"
#include "grade_cgroup.h"
#include "grade_contain.h"
#include "grade_run.h"
#include "grade_sandbox.h"

/* Returns the path of program `name` on PATH, or NULL. */
static char *find_on_path(const char *name)
{
    const char *path = getenv("PATH");
    char *copy = grade_format("%s", path != NULL ? path : "/usr/bin:/bin"), *save = NULL;
    for (char *dir = strtok_r(copy, ":", &save); dir != NULL; dir = strtok_r(NULL, ":", &save)) {
        char *candidate = grade_format("%s/%s", dir, name);
        if (access(candidate, X_OK) == 0)
            return candidate;
    }
    return NULL;
}

/* Chooses the containment that --sandbox asks for (auto, namespaces or fallback): namespaces
 * when bubblewrap is installed and a sandbox of its starts (tried as a student's build would
 * be, through run_student), else the fallback, unless namespaces were asked for; sets
 * g->sandbox to the choice in words (grading tells it). False (reported) when the choice
 * cannot be had. */
bool containment_choose(Grading *g)
{
    const char *asked = g->sandbox != NULL ? g->sandbox : "auto";
    if (strcmp(asked, "auto") != 0 && strcmp(asked, "namespaces") != 0 &&
        strcmp(asked, "fallback") != 0)
        return grade_fail("--sandbox takes auto, namespaces or fallback, got '%s'", asked);
    char *why = "asked for with --sandbox fallback", *bwrap = NULL;
    bool namespaces = false, closes_userns = false;
    if (strcmp(asked, "fallback") != 0) {
        bwrap = find_on_path("bwrap");
        why = "bubblewrap (bwrap) is not installed";
    }
    if (bwrap != NULL) {
        char *version[] = {bwrap, "--version", NULL};
        int major = 0, minor = 0;
        sscanf(run_program(version, NULL, NULL, 60, 0).output, "bubblewrap %d.%d", &major, &minor);
        closes_userns = major > 0 || minor >= 8;
        sandbox_use(bwrap, closes_userns);
        char *probe[] = {"true", NULL};
        RunResult r = run_student(probe, NULL, NULL, 60, 0, &(View){{NULL}, NULL, 0});
        namespaces = r.ok;
        sandbox_use(namespaces ? bwrap : NULL, closes_userns);
        char *said = run_tail(r.output);
        why = r.ok ? NULL
                   : grade_format("bubblewrap cannot make its namespaces here: %s%s%s",
                                  run_describe(&r), said != NULL ? ": " : "",
                                  said != NULL ? said : "");
    }
    if (!namespaces && strcmp(asked, "namespaces") == 0)
        return grade_fail("--sandbox namespaces: %s", why);
    const char *user = contain_active() ? "a user of their own (--run-as)"
                       : geteuid() == 0 ? "root without capabilities (--run-as gives them a "
                                          "user of their own)"
                                        : "your user";
    /* The limits: rlimits always, and a cgroup v2 a run where the grader may make them. */
    const char *cgroups = cgroup_describe();
    char *limits = grade_format("; limits: rlimits%s%s", cgroups[0] != '\0' ? " and " : "",
                                cgroups[0] != '\0' ? cgroups : " (no cgroup v2 to write in here)");
    g->sandbox = namespaces
                     ? grade_format("namespaces (bubblewrap): each build and run in PID, IPC, "
                                    "mount, network and UTS namespaces of its own, seeing "
                                    "only its folders, the toolchain and its scene, as %s%s%s",
                                    user, closes_userns ? "" : " (bubblewrap before 0.8: "
                                                               "user namespaces open inside)",
                                    limits)
                     : grade_format("fallback (%s): each build and run in a session of its "
                                    "own, a clean environment, %s%s",
                                    why, contain_active() ? "as a user of its own (--run-as)"
                                                          : "as your user: nothing stands "
                                                            "between a program and your files",
                                    limits);
    return true;
}
