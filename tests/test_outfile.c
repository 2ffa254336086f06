/* test_outfile.c: output files appear only when complete; failures leave nothing behind. */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "outfile.h"
#include "stop.h"
#include "testing.h"

/* Writes text to path, as an existing file for a test to keep or replace. */
static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    ck_assert_ptr_nonnull(f);
    fputs(text, f);
    ck_assert_int_eq(fclose(f), 0);
}

/* Asserts that path holds exactly text. */
static void assert_contents(const char *path, const char *text)
{
    char buf[256] = "";
    FILE *f = fopen(path, "r");
    ck_assert_msg(f != NULL, "%s does not exist", path);
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    buf[n] = '\0';
    fclose(f);
    ck_assert_str_eq(buf, text);
}

/* Asserts that path does not exist. */
static void assert_missing(const char *path)
{
    ck_assert_msg(access(path, F_OK) != 0, "%s exists", path);
}

/* Returns how many entries of folder start with ".name." (temporaries of name). */
static int count_temporaries(const char *folder, const char *name)
{
    char prefix[256];
    snprintf(prefix, sizeof prefix, ".%s.", name);
    DIR *d = opendir(folder);
    if (d == NULL)
        return 0;
    int count = 0;
    for (struct dirent *e; (e = readdir(d)) != NULL;)
        count += strncmp(e->d_name, prefix, strlen(prefix)) == 0;
    closedir(d);
    return count;
}

/* Tells whether to skip a test of permissions, which root ignores, saying so. */
static bool skipped_as_root(const char *what)
{
    if (geteuid() != 0)
        return false;
    fprintf(stderr, "test_outfile: running as root, which ignores permissions: %s skipped\n", what);
    return true;
}

/* Every test runs twice (a loop test, _i = 0 and 1): with the unnamed temporary the
 * system gives (O_TMPFILE), then with the named one used where it cannot. */
static void choose_temporary_in(const char *test, int i)
{
    outfile_avoid_tmpfile = i == 1;
    /* Each run in a folder of its own, as all share the program's scratch folder. */
    char dir[128];
    snprintf(dir, sizeof dir, "%s-%d", test, i);
    ck_assert_int_eq(mkdir(dir, 0777), 0);
    ck_assert_int_eq(chdir(dir), 0);
}
#define choose_temporary(i) choose_temporary_in(__func__, (i))

/* Opens path as an OutFile, asserting success. */
static OutFile open_ok(const char *path)
{
    OutFile out;
    Error err = {""};
    ck_assert_msg(outfile_open(&out, path, &err), "%s: %s", path, err.text);
    ck_assert_ptr_nonnull(out.file);
    return out;
}

/* Commits out, asserting that it succeeds. */
static void commit_ok(OutFile *out)
{
    Error err = {""};
    ck_assert_msg(outfile_commit(out, &err), "%s", err.text);
}

/* Asserts that outfile_check(path) fails with exactly the message expected. */
static void assert_check_fails(const char *path, const char *expected)
{
    Error err = {""};
    ck_assert_msg(!outfile_check(path, &err), "%s passed the check", path);
    ck_assert_str_eq(err.text, expected);
}

START_TEST(commit_makes_the_file)
{
    choose_temporary(_i);
    mkdir("out", 0777);
    OutFile out = open_ok("out/a.txt");
    /* The temporary has no name, or a hidden one beside the target; the target is not
     * there yet. */
    if (out.unnamed) {
        ck_assert_ptr_null(out.temp_path);
        ck_assert_int_eq(count_temporaries("out", "a.txt"), 0);
    } else {
        ck_assert_int_eq(strncmp(out.temp_path, "out/.a.txt.", 11), 0);
        ck_assert_int_eq(count_temporaries("out", "a.txt"), 1);
    }
    fputs("complete contents\n", out.file);
    assert_missing("out/a.txt");
    commit_ok(&out);
    assert_contents("out/a.txt", "complete contents\n");
    ck_assert_int_eq(count_temporaries("out", "a.txt"), 0);
    ck_assert_ptr_null(out.path);
    ck_assert_ptr_null(out.temp_path);
}
END_TEST

START_TEST(commit_in_the_working_folder)
{
    choose_temporary(_i);
    OutFile out = open_ok("plain.txt");
    ck_assert(out.unnamed || strncmp(out.temp_path, ".plain.txt.", 11) == 0);
    fputs("x", out.file);
    commit_ok(&out);
    assert_contents("plain.txt", "x");
    ck_assert_int_eq(count_temporaries(".", "plain.txt"), 0);
}
END_TEST

START_TEST(commit_gives_normal_permissions)
{
    choose_temporary(_i);
    /* mkstemp makes files 0600; the result should be 0666 less the umask. */
    mode_t old = umask(022);
    OutFile out = open_ok("perm.txt");
    commit_ok(&out);
    umask(old);
    struct stat st;
    ck_assert_int_eq(stat("perm.txt", &st), 0);
    ck_assert_uint_eq(st.st_mode & 0777, 0644);
}
END_TEST

START_TEST(commit_replaces_an_existing_file)
{
    choose_temporary(_i);
    write_text("r.txt", "old");
    OutFile out = open_ok("r.txt");
    fputs("new", out.file);
    commit_ok(&out);
    assert_contents("r.txt", "new");
    ck_assert_int_eq(count_temporaries(".", "r.txt"), 0);
}
END_TEST

START_TEST(abort_leaves_nothing)
{
    choose_temporary(_i);
    OutFile out = open_ok("gone.txt");
    fputs("half", out.file);
    outfile_abort(&out);
    assert_missing("gone.txt");
    ck_assert_int_eq(count_temporaries(".", "gone.txt"), 0);
    ck_assert_ptr_null(out.file);
    /* Aborting twice, or a zeroed OutFile, is harmless. */
    outfile_abort(&out);
    OutFile zero = {0};
    outfile_abort(&zero);
}
END_TEST

START_TEST(abort_keeps_an_existing_file)
{
    choose_temporary(_i);
    write_text("keep.txt", "precious");
    OutFile out = open_ok("keep.txt");
    fputs("half", out.file);
    outfile_abort(&out);
    assert_contents("keep.txt", "precious");
    ck_assert_int_eq(count_temporaries(".", "keep.txt"), 0);
}
END_TEST

START_TEST(commit_fails_when_the_folder_is_removed)
{
    choose_temporary(_i);
    mkdir("doomed", 0777);
    OutFile out = open_ok("doomed/a.txt");
    fputs("contents", out.file);
    /* Removing the folder means removing a named temporary first: rename has nowhere to
     * go; an unnamed one has no name to link. */
    if (!out.unnamed)
        ck_assert_int_eq(unlink(out.temp_path), 0);
    ck_assert_int_eq(rmdir("doomed"), 0);
    Error err = {""};
    ck_assert(!outfile_commit(&out, &err));
    ck_assert_ptr_nonnull(strstr(err.text, "No such file or directory"));
    assert_missing("doomed");
    ck_assert_ptr_null(out.temp_path);
}
END_TEST

START_TEST(commit_detects_a_full_disk)
{
    choose_temporary(_i);
    /* /dev/full fails every write with ENOSPC: put it under the temporary's stream. */
    int full = open("/dev/full", O_WRONLY);
    if (full < 0) {
        fprintf(stderr, "test_outfile: no /dev/full here: full-disk test skipped\n");
        return;
    }
    write_text("full.txt", "old");
    OutFile out = open_ok("full.txt");
    ck_assert_int_ne(dup2(full, fileno(out.file)), -1);
    close(full);
    fputs("new contents that cannot be written", out.file);
    Error err = {""};
    ck_assert(!outfile_commit(&out, &err));
    ck_assert_str_eq(err.text, strerror(ENOSPC));
    assert_contents("full.txt", "old");
    ck_assert_int_eq(count_temporaries(".", "full.txt"), 0);
}
END_TEST

START_TEST(commit_fails_when_the_folder_is_not_writable)
{
    choose_temporary(_i);
    if (skipped_as_root("the unwritable-folder test"))
        return;
    mkdir("locked", 0777);
    OutFile out = open_ok("locked/a.txt");
    fputs("x", out.file);
    chmod("locked", 0555);
    Error err = {""};
    /* The rename fails; the temporary cannot be removed either, in a locked folder,
     * so the message names it. */
    ck_assert(!outfile_commit(&out, &err));
    ck_assert_ptr_nonnull(strstr(err.text, "Permission denied"));
    if (_i == 1) {
        ck_assert_ptr_nonnull(strstr(err.text, "(and the temporary 'locked/.a.txt."));
        ck_assert_ptr_nonnull(strstr(err.text, "' could not be removed)"));
    }
    assert_missing("locked/a.txt");
    chmod("locked", 0777);
}
END_TEST

START_TEST(commit_after_a_stop_request)
{
    choose_temporary(_i);
    write_text("stop.txt", "old");
    OutFile out = open_ok("stop.txt");
    fputs("new", out.file);
    stop_request(SIGINT);
    Error err = {""};
    bool committed = outfile_commit(&out, &err);
    stop_reset();
    ck_assert(!committed);
    ck_assert_str_eq(err.text, "interrupted");
    assert_contents("stop.txt", "old");
    ck_assert_int_eq(count_temporaries(".", "stop.txt"), 0);
}
END_TEST

START_TEST(commit_without_open)
{
    OutFile out;
    Error err = {""};
    ck_assert(!outfile_open(&out, "nope/x.txt", &err));
    ck_assert_ptr_null(out.file);
    outfile_abort(&out);
    ck_assert(!outfile_commit(&out, &err));
}
END_TEST

START_TEST(check_errors)
{
    Error err = {""};
    ck_assert(outfile_check("new.png", &err));
    mkdir("sub", 0777);
    ck_assert(outfile_check("sub/new.png", &err));
    write_text("exists.png", "x");
    ck_assert(outfile_check("exists.png", &err));
    assert_check_fails("missing/x.png", "folder 'missing' does not exist");
    assert_check_fails("missing/deeper/x.png", "folder 'missing/deeper' does not exist");
    assert_check_fails("sub", "it is a folder");
    assert_check_fails("sub/", "not a file name");
    assert_check_fails("", "not a file name");
    /* Parent is a plain file: the folder exists as a name, but is not a folder. */
    assert_check_fails("exists.png/x.png", "'exists.png' is not a folder");
    assert_check_fails("exists.png/a/x.png", "'exists.png/a' is not a folder");
    assert_check_fails("/dev/null", "it exists and is not a regular file");
}
END_TEST

START_TEST(check_permissions)
{
    if (skipped_as_root("the permission checks"))
        return;
    mkdir("ro", 0555);
    assert_check_fails("ro/x.png", "folder 'ro' is not writable");
    write_text("ro.png", "x");
    chmod("ro.png", 0444);
    assert_check_fails("ro.png", "the file exists and is not writable");
    chmod("ro", 0777);
}
END_TEST

START_TEST(killed_while_writing_leaves_nothing)
{
    choose_temporary(_i);
    /* A child writes a megabyte and is killed (SIGKILL: no handler runs) before it commits. */
    mkdir("k", 0777);
    pid_t pid = fork();
    ck_assert_int_ge(pid, 0);
    if (pid == 0) {
        OutFile out;
        Error err;
        if (!outfile_open(&out, "k/image.pfm", &err))
            _exit(1);
        for (int k = 0; k < 1024; k++)
            fprintf(out.file, "%01023d\n", k);
        fflush(out.file);
        raise(SIGKILL);
    }
    int status;
    ck_assert_int_eq(waitpid(pid, &status, 0), pid);
    ck_assert(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
    /* Unnamed, nothing is left; named, the hidden temporary is (the documented limit). */
    ck_assert_int_eq(count_temporaries("k", "image.pfm"), _i == 0 ? 0 : 1);
    assert_missing("k/image.pfm");
}
END_TEST

/* Returns a name of n characters: "n" then x's, ".png" at the end. */
static const char *long_name(int n)
{
    static char name[512];
    memset(name, 'x', (size_t)n);
    memcpy(name + n - 4, ".png", 5);
    return name;
}

START_TEST(long_names)
{
    choose_temporary(_i);
    /* 250 characters: ".NAME.XXXXXX" would be 258, too long for a name; the temporary
     * gets a shorter one, new file or not. */
    const char *name = long_name(250);
    for (int pass = 0; pass < 2; pass++) {
        OutFile out = open_ok(name);
        fputs(pass == 0 ? "first" : "second", out.file);
        commit_ok(&out);
        assert_contents(name, pass == 0 ? "first" : "second");
    }
    ck_assert_int_eq(count_temporaries(".", "raytra"), 0);
    /* 256 characters: no file can have that name, which the check says before a render. */
    char expected[128];
    snprintf(expected, sizeof expected,
             "the name is 256 characters long; the folder takes at most %ld",
             pathconf(".", _PC_NAME_MAX));
    assert_check_fails(long_name(256), expected);
}
END_TEST

START_TEST(sticky_folder_of_another_user)
{
    /* In a sticky folder (mode 1777, as /tmp) a file of another user cannot be replaced:
     * rename would fail after the render. As root the test plays that user with seteuid. */
    if (geteuid() != 0) {
        fprintf(stderr, "test_outfile: not root, cannot make another user's file: sticky "
                        "folder test skipped\n");
        return;
    }
    /* The other user must reach the folder through the scratch folder (0700). */
    chmod(".", 0711);
    mkdir("sticky", 0777);
    chmod("sticky", 01777);
    write_text("sticky/theirs.png", "theirs");
    chmod("sticky/theirs.png", 0666);
    ck_assert_int_eq(chown("sticky/theirs.png", 1, 1), 0);
    ck_assert_int_eq(seteuid(65534), 0);
    Error err = {""};
    bool ok = outfile_check("sticky/theirs.png", &err);
    /* The check is right: that user may make a file there, but not rename it onto theirs. */
    FILE *mine = fopen("sticky/mine", "w");
    int renamed = rename("sticky/mine", "sticky/theirs.png");
    int rename_errno = errno;
    ck_assert_int_eq(seteuid(0), 0);
    ck_assert_ptr_nonnull(mine);
    fclose(mine);
    ck_assert_int_eq(renamed, -1);
    ck_assert_int_eq(rename_errno, EPERM);
    ck_assert(!ok);
    ck_assert_contains(err.text, "the file belongs to another user");
    assert_contents("sticky/theirs.png", "theirs");
}
END_TEST

START_TEST(check_leaves_nothing)
{
    choose_temporary(_i);
    Error err;
    mkdir("c", 0777);
    ck_assert(outfile_check("c/x.png", &err));
    ck_assert_int_eq(count_temporaries("c", "x.png"), 0);
    assert_missing("c/x.png");
}
END_TEST

/* The output file's tests. */
static Suite *outfile_suite(void)
{
    Suite *s = suite_create("outfile");
    TCase *tc = tcase_create("outfile");
    tcase_add_loop_test(tc, commit_makes_the_file, 0, 2);
    tcase_add_loop_test(tc, commit_in_the_working_folder, 0, 2);
    tcase_add_loop_test(tc, commit_gives_normal_permissions, 0, 2);
    tcase_add_loop_test(tc, commit_replaces_an_existing_file, 0, 2);
    tcase_add_loop_test(tc, abort_leaves_nothing, 0, 2);
    tcase_add_loop_test(tc, abort_keeps_an_existing_file, 0, 2);
    tcase_add_loop_test(tc, commit_fails_when_the_folder_is_removed, 0, 2);
    tcase_add_loop_test(tc, commit_detects_a_full_disk, 0, 2);
    tcase_add_loop_test(tc, commit_fails_when_the_folder_is_not_writable, 0, 2);
    tcase_add_loop_test(tc, commit_after_a_stop_request, 0, 2);
    tcase_add_test(tc, commit_without_open);
    tcase_add_test(tc, check_errors);
    tcase_add_test(tc, check_permissions);
    tcase_add_loop_test(tc, killed_while_writing_leaves_nothing, 0, 2);
    tcase_add_loop_test(tc, long_names, 0, 2);
    tcase_add_test(tc, sticky_folder_of_another_user);
    tcase_add_loop_test(tc, check_leaves_nothing, 0, 2);
    suite_add_tcase(s, tc);
    return s;
}

TEST_MAIN(outfile_suite)
