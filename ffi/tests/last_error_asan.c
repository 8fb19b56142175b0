/* The kef_last_error guarantee under AddressSanitizer (CI: .ci/ffi.sh,
 * built with -fsanitize=address against libkefriction.a). The message
 * pointer is read in the same expression as a failing constructor (its
 * arguments in either order: a constructor's message is formatted when it
 * fails), after a failing lookup (whose message kef_last_error formats),
 * across other failures and after freeing handles: ASan reports any read
 * of freed or out-of-bounds memory. Prints
 * the lines CI checks; exit status 0 when all hold. */
#include <kefriction.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

int main(void) {
    double mu = 42.0;
    int failures = 0;
    /* The guarantee in one line: C leaves the order of the two calls open. */
    printf("%d %s\n", kef_model_mu(NAN, 0.001, 0.04, 0.3, 0.004, 0.01, &mu), kef_last_error());

    /* Taken first, read after kef_last_error formats the later call's message. */
    const char *early = kef_last_error();
    int code = kef_table_mu(kef_table_default(), 9.0, 0.001, 0.01, &mu);
    failures += kef_last_error() != early;
    printf("%d %s\n", code, early);
    failures += code != KEF_ERR_DOMAIN || strstr(early, "psi = 9") == NULL;

    /* A message from a failure on a handle, read after the handle is freed. */
    kef_curve *curve = kef_curve_from_table(kef_table_default(), 1.0, 0.003);
    if (curve == NULL) return 1;
    code = kef_curve_mu(curve, 0.5, &mu);
    kef_curve_free(curve);
    printf("%d %s\n", code, kef_last_error());
    failures += code != KEF_ERR_DOMAIN || strstr(early, "f_star = 0.5") == NULL;

    /* A long message (a long missing path) is cut, still NUL-terminated. */
    char path[4096];
    memset(path, 'x', sizeof path - 1);
    path[0] = '/';
    path[sizeof path - 1] = '\0';
    failures += kef_table_load(path) != NULL;
    size_t n = strlen(kef_last_error());
    printf("long message: %zu bytes\n", n);
    failures += n == 0 || n > 1023;

    failures += mu != 42.0; /* no output written on failure */
    printf("version %s\n", kef_version());
    return failures != 0;
}
