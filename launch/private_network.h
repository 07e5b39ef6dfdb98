/* Isolation of a run: a private network namespace whose loopback carries the
 * multicast route, so no packet leaves the machine and runs side by side cannot
 * hear each other. */
#ifndef FSI_PRIVATE_NETWORK_H
#define FSI_PRIVATE_NETWORK_H

/* Moves the calling (single-threaded) process into a new user + network namespace,
 * brings loopback up and routes 224.0.0.0/4 on it. Children inherit it.
 * Returns 0, or -1 with a message. */
int fsi_enter_private_network(void);

/* The same namespace without bringing loopback up: no network at all, for
 * processes that must not use one (`fsi replay`). Returns 0, or -1 with a message. */
int fsi_leave_network(void);

#endif
