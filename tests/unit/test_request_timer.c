/* When a waiting process asks again for a missing message: not before the wait is
 * overdue by what such waits took, then at short intervals growing to a cap,
 * and an estimate that waits recovered by resent copies do not inflate. */
#include <math.h>

#include "request_timer.h"

#include "unit_check.h"

/* Requests a wait of 'seconds' would send, from start to arrival. */
static int requests_during(fsi_wait_estimate *e, double seconds, int original, double loss)
{
    fsi_request_timer t;
    fsi_request_timer_start(&t, e, 0.0, loss);
    int n = 0;
    for (double now = 0.0; now < seconds; now += 1e-5)
        n += fsi_request_timer_due(&t, now, loss);
    fsi_request_timer_arrived(&t, seconds, original, loss);
    return n;
}

int main(void)
{
    fsi_wait_estimate e = {0};
    CHECK(fsi_wait_overdue(&e) == FSI_REQUEST_OVERDUE_FIRST_S, "unmeasured: %g", fsi_wait_overdue(&e));
    CHECK(fsi_wait_overdue(NULL) == FSI_REQUEST_OVERDUE_FIRST_S, "NULL estimate");

    /* Steady waits of 30 ms (a partner computing): after the first, none asks. */
    int asked = 0;
    for (int i = 0; i < 100; i++)
        asked += requests_during(&e, 0.030, 1, 0.0) * (i > 0);
    CHECK(asked == 0, "%d requests in 99 steady 30 ms waits", asked);
    CHECK(fabs(fsi_wait_overdue(&e) - FSI_REQUEST_OVERDUE_MAX_S) < 1e-12 ||
              fsi_wait_overdue(&e) > 0.030,
          "overdue %g s is not after the usual 30 ms wait", fsi_wait_overdue(&e));

    /* Steady waits of 0.1 ms (a loopback round trip): overdue at the floor. */
    fsi_wait_estimate fast = {0};
    for (int i = 0; i < 50; i++)
        requests_during(&fast, 1e-4, 1, 0.0);
    CHECK(fsi_wait_overdue(&fast) == FSI_REQUEST_OVERDUE_MIN_S, "fast waits: overdue %g s",
          fsi_wait_overdue(&fast));

    /* A lost message on a lossy bus: first request when overdue, then 0.5 ms,
     * 0.75 ms, ... up to the 20 ms cap: 1 s of waiting costs about 50 + 10 requests. */
    fsi_request_timer t;
    fsi_request_timer_start(&t, &fast, 0.0, 0.5);
    CHECK(!fsi_request_timer_due(&t, FSI_REQUEST_OVERDUE_MIN_S * 0.99, 0.5), "asked before overdue");
    CHECK(fsi_request_timer_due(&t, FSI_REQUEST_OVERDUE_MIN_S, 0.5), "not asked when overdue");
    double first = t.next_request - FSI_REQUEST_OVERDUE_MIN_S;
    CHECK(fabs(first - FSI_REQUEST_REPEAT_FIRST_S) < 1e-12, "second request after %g s", first);
    int n = requests_during(&fast, 1.0, 0, 0.5);
    CHECK(n > 40 && n < 80, "%d requests in 1 s", n);
    /* A late one on a loss-free bus: doubling to 0.25 s, about 10 requests in 1 s. */
    fsi_wait_estimate late = fast;
    fsi_request_timer_start(&t, &late, 0.0, 0.0);
    n = 0;
    for (double now = 0.0; now < 1.0; now += 1e-5)
        n += fsi_request_timer_due(&t, now, 0.0);
    CHECK(n >= 8 && n <= 14, "%d requests in 1 s on a loss-free bus", n);
    /* Loss measured during such a wait: it repeats at the short lossy intervals. */
    fsi_request_timer_start(&t, &late, 0.0, 0.0);
    n = 0;
    for (double now = 0.0; now < 1.0; now += 1e-5)
        n += fsi_request_timer_due(&t, now, now < 0.1 ? 0.0 : 0.5);
    CHECK(n > 40, "only %d requests in 1 s with loss found after 0.1 s", n);
    double before = fsi_wait_overdue(&fast);
    CHECK(before == FSI_REQUEST_OVERDUE_MIN_S, "a resent copy changed the estimate: %g", before);

    /* Under loss, waits ended after requests by messages that look new may still be
     * recoveries: they do not raise the estimate ... */
    for (int i = 0; i < 50; i++)
        requests_during(&fast, 0.01, 1, 0.5);
    CHECK(fsi_wait_overdue(&fast) == FSI_REQUEST_OVERDUE_MIN_S,
          "recoveries under loss raised the overdue time to %g s", fsi_wait_overdue(&fast));
    /* ... but on a loss-free bus such waits were late, and it learns them. */
    for (int i = 0; i < 50; i++)
        requests_during(&fast, 0.01, 1, 0.0);
    CHECK(fsi_wait_overdue(&fast) > 0.01, "waits grown to 10 ms: overdue still %g s",
          fsi_wait_overdue(&fast));
    return unit_check_report("test_request_timer");
}
