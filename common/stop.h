/* stop.h: a request to stop early, made by SIGINT or SIGTERM and polled by long loops. */
#ifndef RAYTRA_STOP_H
#define RAYTRA_STOP_H

#include <stdbool.h>

void stop_install(void);
void stop_request(int signal_number);
bool stop_requested(void);
int stop_signal(void);
void stop_reset(void);

#endif
