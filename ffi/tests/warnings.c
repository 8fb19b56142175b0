/* The plausibility warnings and F* > 1 from C (CI: .ci/ffi.sh; issue 37's
 * case 1): a load below the paper's range sets KEF_WARN_F_STAR_BELOW_RANGE
 * (and, with adhesion, KEF_WARN_ADHESION_DOMINATED) with a message on
 * request; a result inside the range sets none; F* = 2 is KEF_ERR_DOMAIN,
 * mu untouched. Exit status 0 when all hold. */
#include <kefriction.h>
#include <stdio.h>
#include <string.h>

static int failures = 0;

static void expect(int ok, const char *what) {
    if (!ok) {
        fprintf(stderr, "warnings: FAILED: %s\n", what);
        failures++;
    }
}

int main(void) {
    double mu = -1.0;
    kef_clear_warnings();
    expect(kef_model_mu_with(NULL, 1.0, 0.001, 0.01, &mu) == KEF_OK, "F* = 0.01: KEF_OK");
    expect(kef_warnings() == 0, "F* = 0.01: no warning");

    expect(kef_model_mu_with(NULL, 0.85, 0.0013, 1e-7, &mu) == KEF_OK, "F* = 1e-7: KEF_OK");
    int w = kef_warnings();
    expect((w & KEF_WARN_F_STAR_BELOW_RANGE) != 0, "F* = 1e-7: below the range");
    expect((w & KEF_WARN_ADHESION_DOMINATED) != 0, "F* = 1e-7: mu > 1, adhesion-dominated");
    const char *m = kef_warning_message(KEF_WARN_F_STAR_BELOW_RANGE);
    expect(strncmp(m, "F* = 1e-7 is below the range", 28) == 0, "F* = 1e-7: its message");
    printf("warning %d: %s\n", KEF_WARN_F_STAR_BELOW_RANGE, m);
    kef_clear_warnings();
    expect(kef_warnings() == 0, "cleared");

    double untouched = -1.0;
    expect(kef_model_mu_with(NULL, 0.85, 0.0013, 2.0, &untouched) == KEF_ERR_DOMAIN, "F* = 2: KEF_ERR_DOMAIN");
    expect(untouched == -1.0, "F* = 2: mu untouched");
    expect(strstr(kef_last_error(), "must be <= 1") != NULL, "F* = 2: the message names the bound");
    printf("F* = 2: %s\n", kef_last_error());
    return failures == 0 ? 0 : 1;
}
