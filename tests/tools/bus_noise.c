/* Test tool: floods an LCM network with what a run must ignore: random bytes on our
 * channels, messages of one type on another type's channel, well-formed messages of
 * another run and of another protocol version, and unknown channels.
 * usage: fsi-test-bus-noise URL SECONDS */
#include <lcm/lcm.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "fsi_abort_t.h"
#include "fsi_step_t.h"
#include "protocol.h"

static void publish_step(lcm_t *lcm, int64_t run_id, int version, int window)
{
    fsi_step_t s = {0};
    s.header.protocol_version = version;
    s.header.run_id = run_id;
    s.header.window = window;
    s.header.sender = FSI_COUPLER_NAME;   /* impersonation: only the run id gives it away */
    s.t = 0.0;
    s.dt = 1.0;
    s.flags = FSI_STEP_FINISH;
    s.frame = 0;
    fsi_step_t_publish(lcm, fsi_msg_channel(FSI_MSG_STEP), &s);
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: %s URL SECONDS\n", argv[0]);
        return 2;
    }
    lcm_t *lcm = lcm_create(argv[1]);
    if (!lcm)
        return 1;
    double seconds = atof(argv[2]);
    srand(12345);
    unsigned char junk[2048];
    long sent = 0;
    struct timespec start, now;
    clock_gettime(CLOCK_MONOTONIC, &start);
    do {
        for (int type = 0; type < FSI_MSG_COUNT; type++) {
            int len = 1 + rand() % (int)sizeof junk;
            for (int i = 0; i < len; i++)
                junk[i] = (unsigned char)rand();
            lcm_publish(lcm, fsi_msg_channel((fsi_msg_type)type), junk, (unsigned)len);
        }
        publish_step(lcm, 1 + rand(), FSI_PROTOCOL_VERSION, rand() % 1000);   /* another run */
        publish_step(lcm, 0, FSI_PROTOCOL_VERSION + 7, rand() % 1000);       /* other version */
        fsi_abort_t a = {0};
        a.header.protocol_version = FSI_PROTOCOL_VERSION;
        a.header.sender = "solid";
        a.culprit = "solid";
        a.reason = "garbage";
        fsi_abort_t_publish(lcm, fsi_msg_channel(FSI_MSG_DONE), &a);         /* wrong type */
        lcm_publish(lcm, "FSI_BOGUS", junk, 16);                             /* unknown */
        lcm_publish(lcm, "SOMEONE_ELSE", junk, 64);
        sent += FSI_MSG_COUNT + 5;
        usleep(5000);
        clock_gettime(CLOCK_MONOTONIC, &now);
    } while ((double)(now.tv_sec - start.tv_sec) + 1e-9 * (double)(now.tv_nsec - start.tv_nsec) <
             seconds);
    printf("bus noise: %ld messages\n", sent);
    lcm_destroy(lcm);
    return 0;
}
