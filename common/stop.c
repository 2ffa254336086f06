/* stop.c: turning SIGINT and SIGTERM into a flag that the render loop and file writer poll. */
#include "stop.h"

#include <signal.h>
#include <stdatomic.h>
#include <string.h>

/* The signal that asked to stop, or 0. Lock-free atomics are safe in a handler. */
static atomic_int requested;

/* The handler: the first signal asks politely, a second one kills at once. */
static void on_signal(int sig)
{
    if (atomic_load(&requested) != 0) {
        signal(sig, SIG_DFL);
        raise(sig);
        return;
    }
    stop_request(sig);
}

/* Makes SIGINT and SIGTERM request a stop instead of killing the process. */
void stop_install(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}

/* Asks every loop that polls stop_requested to stop; safe in a signal handler. */
void stop_request(int signal_number)
{
    atomic_store(&requested, signal_number);
}

/* Tells whether a stop was requested. */
bool stop_requested(void)
{
    return atomic_load_explicit(&requested, memory_order_relaxed) != 0;
}

/* Returns the signal that requested the stop, or 0. */
int stop_signal(void)
{
    return atomic_load(&requested);
}

/* Forgets a stop request (for tests). */
void stop_reset(void)
{
    atomic_store(&requested, 0);
}
