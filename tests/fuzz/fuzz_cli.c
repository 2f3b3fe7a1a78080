/* SPDX-License-Identifier: MIT */
/*
 * fuzz_cli.c - libFuzzer harness for the command-line tool's input paths.
 * The CLI's sources are compiled into this program with main renamed
 * (vor_cli_main). The fuzz input is
 *
 *     COMMAND ARG ARG ...      the first line: the command line; the words
 *                              @1 and @2 name the input files below, @out
 *                              an output file
 *     FILE 1 (also stdin)      the lines up to a line "---"
 *     ---
 *     FILE 2                   the rest
 *
 * Each input runs in a forked child (the CLI ends errors with exit(2)):
 * it must exit with 0 or 2, never crash, never be killed, never hang,
 * and on status 2 leave stdout empty and write no output file. A child's
 * coverage does not reach the fuzzer, so the committed seeds cover every
 * command and option and the mutations work from them.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "fuzz_common.h"

int vor_cli_main(int argc, char **argv);

/* The CLI's sources are compiled with -Dexit=vor_fuzz_cli_exit: its exits
 * happen in the child and must skip libFuzzer's atexit check (which would
 * report any exit of the target as a finding). */
void vor_fuzz_cli_exit(int status)
{
    fflush(NULL);
    _exit(status);
}

#define MOST_WORDS 24
#define MOST_PIXELS 65536L /* larger frames only cost time */

static char directory[64];
static char input_path[2][96], output_path[96], stdout_path[96];

static int write_file(const char *path, const uint8_t *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    if (f == NULL)
        return 0;
    int ok = fwrite(data, 1, size, f) == size;
    return fclose(f) == 0 && ok;
}

static long file_size(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (long)st.st_size : -1L;
}

/* The frame size an argument list asks for ("--size W H" or "--size=W,H"),
 * so huge frames can be skipped. */
static long pixels_asked(int argc, char **argv)
{
    long most = 0;
    for (int a = 0; a < argc; a++)
        if ((strcmp(argv[a], "--size") == 0 && a + 2 < argc) || strncmp(argv[a], "--size=", 7) == 0) {
            char *end = NULL;
            long w = strtol(argv[a][6] == '=' ? argv[a] + 7 : argv[a + 1], &end, 10);
            long h = strtol(argv[a][6] == '=' ? (*end == ',' ? end + 1 : end) : argv[a + 2], NULL, 10);
            long p = (w > 0 && h > 0 && w <= MOST_PIXELS && h <= MOST_PIXELS) ? w * h : MOST_PIXELS + 1;
            most = p > most ? p : most;
        }
    return most;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (directory[0] == '\0') {
        snprintf(directory, sizeof directory, "/tmp/vor-fuzz-cli-%ld", (long)getpid());
        mkdir(directory, 0700);
        for (int i = 0; i < 2; i++)
            snprintf(input_path[i], sizeof input_path[i], "%s/in%d", directory, i + 1);
        snprintf(output_path, sizeof output_path, "%s/out", directory);
        snprintf(stdout_path, sizeof stdout_path, "%s/stdout", directory);
    }
    const uint8_t *line_end = memchr(data, '\n', size);
    size_t line_length = line_end ? (size_t)(line_end - data) : size;
    if (line_length > 512)
        return 0;
    char line[513];
    memcpy(line, data, line_length);
    line[line_length] = '\0';
    if (strlen(line) != line_length)
        return 0; /* a NUL inside the command line: no shell could pass it */

    const uint8_t *rest = line_end ? line_end + 1 : data + size;
    size_t rest_size = (size_t)(data + size - rest);
    size_t first_size = rest_size;
    for (size_t i = 0; i + 4 <= rest_size; i++)
        if ((i == 0 || rest[i - 1] == '\n') && memcmp(rest + i, "---\n", 4) == 0) {
            first_size = i;
            break;
        }
    size_t second_at = first_size + (first_size < rest_size ? 4u : 0u);
    if (!write_file(input_path[0], rest, first_size) ||
        !write_file(input_path[1], rest + second_at, rest_size - second_at))
        return 0;
    unlink(output_path);
    unlink(stdout_path);

    char *argv[MOST_WORDS + 2];
    int argc = 0;
    argv[argc++] = "vor";
    for (char *word = strtok(line, " \t\r"); word && argc <= MOST_WORDS; word = strtok(NULL, " \t\r"))
        argv[argc++] = strcmp(word, "@1") == 0   ? input_path[0]
                       : strcmp(word, "@2") == 0 ? input_path[1]
                       : strcmp(word, "@out") == 0 ? output_path
                                                   : word;
    argv[argc] = NULL;
    if (pixels_asked(argc, argv) > MOST_PIXELS)
        return 0;
    /* the child runs in the private directory: a path the fuzzer made up
     * (an output file named "-u") lands there, and no word may leave it */
    for (int a = 1; a < argc; a++)
        if (argv[a] != input_path[0] && argv[a] != input_path[1] && argv[a] != output_path &&
            strchr(argv[a], '/') != NULL)
            return 0;

    fflush(NULL);
    pid_t child = fork();
    if (child == 0) {
        int in = open(input_path[0], O_RDONLY);
        int out = open(stdout_path, O_WRONLY | O_CREAT | O_TRUNC, 0600);
        int null = open("/dev/null", O_WRONLY);
        if (in < 0 || out < 0 || null < 0 || chdir(directory) != 0)
            _exit(3);
        dup2(in, 0);
        dup2(out, 1);
        dup2(getenv("VOR_FUZZ_CLI_STDERR") ? 2 : null, 2);
        signal(SIGALRM, SIG_DFL); /* not libFuzzer's timeout handler */
        alarm(20);                /* a hang ends in SIGALRM: a finding */
        vor_fuzz_cli_exit(vor_cli_main(argc, argv));
    }
    int status = 0;
    pid_t waited;
    do /* libFuzzer's own timer interrupts the wait */
        waited = waitpid(child, &status, 0);
    while (waited < 0 && errno == EINTR);
    FUZZ_REQUIRE(child > 0 && waited == child, "cli: fork or wait failed");
    FUZZ_REQUIRE(!WIFSIGNALED(status), "cli: killed by a signal (crash or hang)");
    int code = WEXITSTATUS(status);
    if (code != 0 && code != 2)
        fprintf(stderr, "cli: exit status %d\n", code);
    FUZZ_REQUIRE(code == 0 || code == 2, "cli: an exit status other than 0 or 2 (sanitizer?)");
    if (code == 2) {
        FUZZ_REQUIRE(file_size(stdout_path) == 0, "cli: output on stdout after an error");
        FUZZ_REQUIRE(file_size(output_path) < 0, "cli: an output file after an error");
    }
    return 0;
}
