/* The batches' NaN mode and the stable kef_last_error pointer from C
 * (CI: .ci/ffi.sh). A NaN among valid points in kef_table_mu_batch_nan and
 * kef_curve_mu_batch_nan gives NaN there, kef_table_mu's values
 * elsewhere, n_nan == 1 and KEF_OK; the Stop form leaves the tail
 * untouched; a pointer from kef_last_error taken before a failing call
 * shows that call's message once kef_last_error is called after it (a
 * lookup's message is formatted then). Exit status 0 when all hold. */
#include <kefriction.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static int failures = 0;

static void expect(int ok, const char *what) {
    if (!ok) {
        fprintf(stderr, "batch_nan: FAILED: %s\n", what);
        failures++;
    }
}

int main(void) {
    const kef_table *t = kef_table_default();
    const double psi[5] = {1.0, 2.0, 3.0, 4.0, 5.0};
    const double theta[5] = {0.001, 0.002, 0.003, 0.004, 0.005};
    const double f_star[5] = {1e-4, 1e-3, NAN, 1e-2, 5e-2};
    double mu[5], single;
    size_t n_nan = 99;

    expect(kef_table_mu_batch_nan(t, 5, psi, theta, f_star, mu, &n_nan) == KEF_OK, "table: KEF_OK");
    expect(n_nan == 1, "table: n_nan == 1");
    expect(isnan(mu[2]), "table: NaN at the NaN point");
    for (int i = 0; i < 5; i++) {
        if (i == 2) continue;
        expect(kef_table_mu(t, psi[i], theta[i], f_star[i], &single) == KEF_OK, "table: kef_table_mu");
        expect(mu[i] == single, "table: kef_table_mu's value at a valid point");
    }

    kef_curve *c = kef_curve_from_table(t, 1.0, 0.001);
    expect(c != NULL, "kef_curve_from_table");
    n_nan = 99;
    expect(kef_curve_mu_batch_nan(c, 5, f_star, mu, &n_nan) == KEF_OK, "curve: KEF_OK");
    expect(n_nan == 1 && isnan(mu[2]), "curve: one NaN, at the NaN load");
    for (int i = 0; i < 5; i++) {
        if (i == 2) continue;
        expect(kef_curve_mu(c, f_star[i], &single) == KEF_OK && mu[i] == single, "curve: kef_curve_mu's value");
    }

    /* Stop: the elements before the bad one written, none from it on. */
    double stop[5] = {-1, -1, -1, -1, -1};
    expect(kef_curve_mu_batch(c, 5, f_star, stop) == KEF_ERR_ARGUMENT, "stop: KEF_ERR_ARGUMENT for NaN");
    expect(stop[0] > 0 && stop[1] > 0 && stop[2] == -1 && stop[3] == -1 && stop[4] == -1, "stop: tail untouched");
    expect(strncmp(kef_last_error(), "batch element 2: f_star = NaN", 29) == 0, "stop: the message names element 2");

    /* The pointer stays valid across failures and shows the latest message
     * once kef_last_error has formatted it. */
    const char *message = kef_last_error();
    int code = kef_table_mu(t, 9.0, 0.001, 0.01, &single);
    expect(kef_last_error() == message, "kef_last_error: the same pointer");
    printf("batch_nan: %d %s\n", code, message);
    expect(code == KEF_ERR_DOMAIN && strncmp(message, "psi = 9", 7) == 0, "kef_last_error: the latest message");

    kef_curve_free(c);
    if (failures == 0) printf("batch_nan: ok\n");
    return failures == 0 ? 0 : 1;
}
