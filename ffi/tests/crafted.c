/* The crafted table files of tests/forge.rs through the C ABI (CI runs it
 * under valgrind): each file whose index line says a field must be refused
 * gives NULL from kef_table_load with KEF_ERR_TABLE and a message naming
 * that field; each loadable one answers its query with the expected mu,
 * from the single and the batch lookups.
 * Usage: crafted DIR (DIR/index.tsv as examples/crafted_tables.rs writes). */
#include <kefriction.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

int main(int argc, char **argv) {
    if (argc != 2) { fprintf(stderr, "usage: crafted DIR\n"); return 2; }
    char path[4096], line[8192];
    snprintf(path, sizeof path, "%s/index.tsv", argv[1]);
    FILE *index = fopen(path, "r");
    if (!index) { perror(path); return 2; }
    int files = 0, failures = 0;
    while (fgets(line, sizeof line, index)) {
        char file[256], field[256];
        double psi, theta, f_star, expected;
        /* file<TAB>field<TAB>psi theta f_star<TAB>mu<TAB>name */
        char *tab1 = strchr(line, '\t'), *tab2 = tab1 ? strchr(tab1 + 1, '\t') : NULL;
        if (!tab1 || !tab2 || sscanf(tab2 + 1, "%lf %lf %lf %lf", &psi, &theta, &f_star, &expected) != 4) {
            fprintf(stderr, "bad index line: %s", line);
            return 2;
        }
        snprintf(file, sizeof file, "%.*s", (int)(tab1 - line), line);
        snprintf(field, sizeof field, "%.*s", (int)(tab2 - tab1 - 1), tab1 + 1);
        snprintf(path, sizeof path, "%s/%s", argv[1], file);
        files++;
        kef_table *t = kef_table_load(path);
        if (strcmp(field, "ok") != 0) {
            const char *msg = kef_last_error();
            if (t != NULL || msg == NULL || strstr(msg, field) == NULL) {
                printf("FAIL %s: must be refused naming '%s': %s\n", file, field, t ? "loaded" : msg);
                failures++;
            }
            kef_table_free(t);
            continue;
        }
        if (t == NULL) {
            printf("FAIL %s: refused: %s\n", file, kef_last_error());
            failures++;
            continue;
        }
        double mu = NAN, batch[2] = {NAN, NAN};
        double ps[2] = {psi, psi}, th[2] = {theta, theta}, fs[2] = {f_star, f_star};
        int rc = kef_table_mu(t, psi, theta, f_star, &mu);
        int rc_batch = kef_table_mu_batch(t, 2, ps, th, fs, batch);
        double tolerance = 2e-6 * (1.0 + fabs(log(expected)));
        if (rc != KEF_OK || rc_batch != KEF_OK || !(mu > 0.0) || !isfinite(mu) || batch[0] != mu || batch[1] != mu ||
            !(fabs(mu / expected - 1.0) <= tolerance)) {
            printf("FAIL %s: mu = %.17g (rc %d, batch rc %d, %.17g), expected %.17g\n", file, mu, rc, rc_batch,
                   batch[0], expected);
            failures++;
        }
        kef_table_free(t);
    }
    fclose(index);
    printf("crafted tables through C: %d files, %d failures\n", files, failures);
    return failures == 0 && files > 0 ? 0 : 1;
}
