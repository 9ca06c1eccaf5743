/* Reading CONTACT's printed tables (tests/data/contact_*.csv) in the C
 * tests: a line split into fields, a column found by its header, and the
 * tolerance a printed number carries (half a unit of its last digit). */
#ifndef CREEPWORK_CONTACT_CSV_H
#define CREEPWORK_CONTACT_CSV_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Half a unit of the last printed digit of text ("-0.5655", "1.000E-05"). */
static inline double cw_printed_half_unit(const char* text)
{
    const char* e = strpbrk(text, "Ee");
    const char* dot = strchr(text, '.');
    const size_t mant = e ? (size_t)(e - text) : strlen(text);
    const int decimals = dot && (size_t)(dot - text) < mant ? (int)(mant - (dot - text) - 1) : 0;
    const int exponent = e ? atoi(e + 1) : 0;
    return 0.5 * pow(10.0, exponent - decimals);
}

/* Splits a CSV line in place (the line end cut off); returns the number of
 * fields. */
static inline int cw_csv_split(char* line, char** fields, int max)
{
    line[strcspn(line, "\r\n")] = '\0';
    int n = 0;
    for (char* p = line; n < max;) {
        fields[n++] = p;
        char* c = strchr(p, ',');
        if (!c) break;
        *c = '\0';
        p = c + 1;
    }
    return n;
}

/* The index of the column named name among the header's n fields, -1 when
 * absent. */
static inline int cw_csv_column(char* const* header, int n, const char* name)
{
    for (int k = 0; k < n; ++k)
        if (!strcmp(header[k], name)) return k;
    return -1;
}

#endif
