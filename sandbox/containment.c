/* containment.c: the containment started and chosen (--sandbox): bubblewrap's namespaces where they work here, or the fallback. */
#include "containment.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cgroup.h"
#include "contain.h"
#include "sandbox.h"
#include "spawn.h"

/* Puts the path of program `name` on PATH into path (of size bytes); false when there is none. */
static bool find_on_path(const char *name, char *path, size_t size)
{
    const char *dirs = getenv("PATH");
    for (const char *d = dirs != NULL ? dirs : "/usr/bin:/bin"; *d != '\0';) {
        size_t len = strcspn(d, ":");
        if (snprintf(path, size, "%.*s/%s", (int)len, d, name) < (int)size &&
            access(path, X_OK) == 0)
            return true;
        d += len + (d[len] == ':');
    }
    return false;
}

/* Tells that a run is never asked to stop early. */
static bool never(void)
{
    return false;
}

/* Runs argv as spawn_run does (a student's with view) for at most a minute; puts the first
 * line it printed in said, or how it ended when it printed none; tells whether it exited 0. */
static bool try_run(char *const argv[], const SandboxView *view, char *said, size_t size)
{
    RunResult r = spawn_run(argv, NULL, 60, 0, view, never);
    const char *line = r.output + strspn(r.output, " \t\r\n");
    if (r.ok || line[0] != '\0')
        snprintf(said, size, "%.*s", (int)strcspn(line, "\r\n"), line);
    else if (r.end == RUN_NOT_RUN)
        snprintf(said, size, "not started: %s", strerror(r.status));
    else
        snprintf(said, size, r.end == RUN_EXITED   ? "exit status %d"
                             : r.end == RUN_KILLED ? "killed by signal %d"
                                                   : "still running after 60 s (%d)",
                 r.status);
    return r.ok;
}

/* Starts the containment: a cgroup v2 of the program's where it may make one, and with run_as
 * the keeper (contain_start). Then chooses what --sandbox asks for (auto, namespaces or
 * fallback): namespaces when bubblewrap is installed and a sandbox of its starts (tried as a
 * student's build would be), else the fallback, unless namespaces were asked for. Returns the
 * choice in words, or NULL (reported) when it cannot be had. */
const char *containment_start(const char *run_as, const char *grader_user, int jobs,
                              const char *asked)
{
    static char bwrap[4096], said[1024], why[1200], words[2048];
    cgroup_start();
    if (!contain_start(run_as, grader_user, jobs))
        return NULL;
    asked = asked != NULL ? asked : "auto";
    if (strcmp(asked, "auto") != 0 && strcmp(asked, "namespaces") != 0 &&
        strcmp(asked, "fallback") != 0)
        return sandbox_fail("--sandbox takes auto, namespaces or fallback, got '%s'", asked),
               NULL;
    snprintf(why, sizeof why, "%s", strcmp(asked, "fallback") == 0
                                        ? "asked for with --sandbox fallback"
                                        : "bubblewrap (bwrap) is not installed");
    bool closes_userns = false;
    if (strcmp(asked, "fallback") != 0 && find_on_path("bwrap", bwrap, sizeof bwrap)) {
        char *version[] = {bwrap, "--version", NULL}, *probe[] = {"true", NULL};
        int major = 0, minor = 0;
        try_run(version, NULL, said, sizeof said);
        sscanf(said, "bubblewrap %d.%d", &major, &minor);
        closes_userns = major > 0 || minor >= 8;
        sandbox_use(bwrap, closes_userns);
        bool works = try_run(probe, &(SandboxView){{NULL}, NULL, 0}, said, sizeof said);
        sandbox_use(works ? bwrap : NULL, closes_userns);
        snprintf(why, sizeof why, "bubblewrap cannot make its namespaces here: %s", said);
    }
    if (!sandbox_namespaces() && strcmp(asked, "namespaces") == 0)
        return sandbox_fail("--sandbox namespaces: %s", why), NULL;
    const char *user = contain_users() > 0 ? "a user of their own (--run-as)"
                       : geteuid() == 0 ? "root without capabilities (--run-as gives them a "
                                          "user of their own)"
                                        : "your user";
    /* The limits: rlimits always, and a cgroup v2 a run where there may be one. */
    const char *cgroups = cgroup_describe();
    char limits[256];
    snprintf(limits, sizeof limits, "; limits: rlimits%s%s", cgroups[0] != '\0' ? " and " : "",
             cgroups[0] != '\0' ? cgroups : " (no cgroup v2 to write in here)");
    if (sandbox_namespaces())
        snprintf(words, sizeof words,
                 "namespaces (bubblewrap): each build and run in PID, IPC, mount, network and "
                 "UTS namespaces of its own, seeing only its folders, the toolchain and its "
                 "scene, as %s%s%s",
                 user, closes_userns ? "" : " (bubblewrap before 0.8: user namespaces open inside)",
                 limits);
    else
        snprintf(words, sizeof words,
                 "fallback (%s): each build and run in a session of its own, a clean "
                 "environment, %s%s",
                 why, contain_users() > 0 ? "as a user of their own (--run-as)"
                                       : "as your user: nothing stands between a program and "
                                         "your files",
                 limits);
    return words;
}

/* Ends the containment: removes the cgroup v2 it made, once every run's is gone. */
void containment_finish(void)
{
    cgroup_finish();
}
