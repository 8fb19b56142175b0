/* Many contacts of one surface pair: a curve built once, looked up in the
 * inner loop. Prints a few mu values (machine-readable "mu" lines) and the
 * measured time per lookup; then a friction law of the contact pressure
 * ("law" lines).
 *
 *   cc -O2 -I ffi/include ffi/examples/contacts.c target/release/libkefriction.a \
 *      -lpthread -ldl -lm -o contacts && ./contacts
 */
#include <kefriction.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <math.h>

#define CONTACTS 100000
#define ROUNDS 21

static double seconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int compare(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int check(int code, const char *what) {
    if (code != KEF_OK) {
        fprintf(stderr, "%s failed (%d): %s\n", what, code, kef_last_error());
        exit(1);
    }
    return code;
}

int main(void) {
    const double psi = 1.0, theta = 0.003; /* one surface pair */
    const kef_table *table = kef_table_default();
    kef_curve *curve = kef_curve_from_table(table, psi, theta);
    if (curve == NULL) {
        fprintf(stderr, "kef_curve_from_table: %s\n", kef_last_error());
        return 1;
    }
    /* A few values, for CI to compare with `kefric eval`. */
    const double loads[] = {1e-4, 1e-3, 1e-2, 5e-2};
    for (int i = 0; i < 4; i++) {
        double mu, slope;
        check(kef_curve_mu_with_slope(curve, loads[i], &mu, &slope), "kef_curve_mu_with_slope");
        printf("mu psi=%.17g theta=%.17g f_star=%.17g mu=%.17g dmu_df_star=%.17g\n", psi, theta, loads[i], mu, slope);
    }
    /* An error, as a simulator would see it. */
    double out = 0.0;
    if (kef_curve_mu(curve, 0.5, &out) == KEF_ERR_DOMAIN)
        printf("expected error: %s\n", kef_last_error());

    /* Peaked (leptokurtic) heights: the Pearson distribution of skewness 0
     * and kurtosis 8, by direct integration at psi = 1, theta = 0.001,
     * F* = 1e-4 (0.2529016383; 0.7567111956 for Gaussian heights). A pair
     * outside the Pearson region (K <= Sk^2 + 1) is refused, the handle kept. */
    kef_constants *peaked = kef_constants_new();
    if (peaked == NULL) return 1;
    check(kef_constants_set_distribution(peaked, KEF_DIST_PEARSON, 0.0, 8.0), "kef_constants_set_distribution");
    if (kef_constants_set_distribution(peaked, KEF_DIST_PEARSON, 0.5, 1.2) != KEF_ERR_DOMAIN) {
        fprintf(stderr, "kef_constants_set_distribution accepted kurtosis 1.2 at skewness 0.5\n");
        return 1;
    }
    printf("expected error: %s\n", kef_last_error());
    int family;
    double skewness, kurtosis, peaked_mu;
    check(kef_constants_distribution(peaked, &family, &skewness, &kurtosis), "kef_constants_distribution");
    check(kef_model_mu_with(peaked, 1.0, 0.001, 1e-4, &peaked_mu), "kef_model_mu_with");
    printf("pearson family=%d skewness=%g kurtosis=%g mu=%.10f\n", family, skewness, kurtosis, peaked_mu);
    if (family != KEF_DIST_PEARSON || fabs(peaked_mu - 0.2529016383) > 1e-9) {
        fprintf(stderr, "Pearson(0, 8): mu = %.12f, family %d\n", peaked_mu, family);
        return 1;
    }
    kef_constants_free(peaked);

    /* The inner loop: loads of many contacts, one lookup each. Loads
     * spread log-uniformly over the curve's range (1e-5 to 0.1). */
    double *f = malloc(CONTACTS * sizeof *f), *mu = malloc(CONTACTS * sizeof *mu);
    if (f == NULL || mu == NULL) return 1;
    unsigned long long state = 2004;
    for (int i = 0; i < CONTACTS; i++) {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        double u = (double)(state >> 11) / 9007199254740992.0; /* [0, 1) */
        f[i] = 1e-5 * exp(u * log(1e4));
    }
    double one[ROUNDS], batch[ROUNDS], sum = 0.0;
    for (int r = 0; r < ROUNDS; r++) {
        double t0 = seconds();
        for (int i = 0; i < CONTACTS; i++) {
            check(kef_curve_mu(curve, f[i], &mu[i]), "kef_curve_mu");
        }
        double t1 = seconds();
        check(kef_curve_mu_batch(curve, CONTACTS, f, mu), "kef_curve_mu_batch");
        double t2 = seconds();
        one[r] = (t1 - t0) / CONTACTS * 1e9;
        batch[r] = (t2 - t1) / CONTACTS * 1e9;
        sum += mu[r];
    }
    qsort(one, ROUNDS, sizeof one[0], compare);
    qsort(batch, ROUNDS, sizeof batch[0], compare);
    printf("time per lookup (median of %d rounds of %d contacts): kef_curve_mu %.2f ns, kef_curve_mu_batch %.2f ns (checksum %.6f)\n",
           ROUNDS, CONTACTS, one[ROUNDS / 2], batch[ROUNDS / 2], sum);
    free(f);
    free(mu);
    kef_curve_free(curve);
    kef_table_free((kef_table *)table); /* the default table: a no-op */

    /* A simulator's nodes: the friction law of the contact pressure in Pa
     * (H = 1 GPa, the default range 1e4..1e8 Pa, clamped outside it). An
     * open node (p <= 0) has no mu: NaN in the batch's NaN form. */
    kef_law *law = kef_law_new(NULL, 1.0, 0.001, 1e9, 0.0, 0.0, KEF_LAW_CLAMP);
    if (law == NULL) {
        fprintf(stderr, "kef_law_new: %s\n", kef_last_error());
        return 1;
    }
    double p[4] = {1e5, 1e7, 0.0, 1e9}, law_mu[4], dmu_dp[4];
    size_t open_nodes = 0;
    uint64_t clamped = 0;
    check(kef_law_mu_and_derivative_batch_nan(law, 4, p, law_mu, dmu_dp, &open_nodes), "kef_law batch");
    check(kef_law_clamped(law, 0, &clamped), "kef_law_clamped");
    for (int i = 0; i < 4; i++) printf("law p=%g mu=%.9g dmu_dp=%.6g\n", p[i], law_mu[i], dmu_dp[i]);
    printf("law: %zu open node(s), %llu clamped\n", open_nodes, (unsigned long long)clamped);
    kef_law_free(law);
    return 0;
}
