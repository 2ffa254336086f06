/* grade_time.c: times in ISO 8601 with their time zone (due dates, commits, Gradescope's), and durations, read and written. */
#include "grade_time.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "grade_base.h"

/* Returns the days from 1970-01-01 to the day y-m-d of the proleptic Gregorian calendar
 * (Howard Hinnant's days_from_civil), with no time zone and no library's. */
static long days_from_civil(long y, int m, int d)
{
    y -= m <= 2;
    long era = (y >= 0 ? y : y - 399) / 400;
    long yoe = y - era * 400;
    long doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
    return era * 146097 + yoe * 365 + yoe / 4 - yoe / 100 + doy - 719468;
}

/* Sets *y, *m and *d to the day `days` after 1970-01-01 (civil_from_days). */
static void civil_from_days(long days, long *y, int *m, int *d)
{
    days += 719468;
    long era = (days >= 0 ? days : days - 146096) / 146097;
    long doe = days - era * 146097;
    long yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    long doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    long mp = (5 * doy + 2) / 153;
    *d = (int)(doy - (153 * mp + 2) / 5 + 1);
    *m = (int)(mp < 10 ? mp + 3 : mp - 9);
    *y = yoe + era * 400 + (*m <= 2);
}

/* Reads `count` digits at *p into *v, moving p past them; false when they are not there. */
static bool digits(const char **p, int count, int *v)
{
    *v = 0;
    for (int k = 0; k < count; k++, (*p)++) {
        if (!isdigit((unsigned char)**p))
            return false;
        *v = 10 * *v + (**p - '0');
    }
    return true;
}

/* Reads a time in ISO 8601 with its time zone: YYYY-MM-DDTHH:MM, then :SS and a fraction
 * if given, then Z or an offset (+HH:MM, +HHMM or +HH; - west of UTC), as Gradescope and
 * git write them; sets *when to its seconds since 1970 and *zone to the offset in minutes.
 * False when the text is not such a time, or no such day or hour exists. */
bool time_parse(const char *text, double *when, int *zone)
{
    static const int month_days[] = {31, 29, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
    const char *p = text;
    int y, mo, d, h, mi, s = 0, zh = 0, zm = 0, sign = 1;
    double fraction = 0;
    if (!digits(&p, 4, &y) || *p++ != '-' || !digits(&p, 2, &mo) || *p++ != '-' ||
        !digits(&p, 2, &d) || (*p != 'T' && *p != 't') || (p++, !digits(&p, 2, &h)) ||
        *p++ != ':' || !digits(&p, 2, &mi))
        return false;
    if (*p == ':' && (p++, !digits(&p, 2, &s)))
        return false;
    if (*p == '.' || *p == ',') {
        char *end;
        fraction = strtod(grade_format("0.%.*s", (int)strspn(p + 1, "0123456789"), p + 1), &end);
        p += 1 + strspn(p + 1, "0123456789");
    }
    if (*p == 'Z' || *p == 'z')
        p++;
    else if (*p == '+' || *p == '-') {
        sign = *p++ == '-' ? -1 : 1;
        if (!digits(&p, 2, &zh))
            return false;
        if (*p == ':')
            p++;
        if (*p != '\0' && !digits(&p, 2, &zm))
            return false;
    } else
        return false; /* a time with no zone is not a moment */
    bool leap = (y % 4 == 0 && y % 100 != 0) || y % 400 == 0;
    if (*p != '\0' || mo < 1 || mo > 12 || d < 1 || d > month_days[mo - 1] ||
        (mo == 2 && d == 29 && !leap) || h > 23 || mi > 59 || s > 60 || zh > 14 || zm > 59)
        return false;
    *zone = sign * (60 * zh + zm);
    *when = 86400.0 * days_from_civil(y, mo, d) + 3600.0 * h + 60.0 * mi + s + fraction -
            60.0 * *zone;
    return true;
}

/* Returns the time `when` (seconds since 1970) in ISO 8601 in time zone `zone` (minutes east
 * of UTC), to the second: 2026-03-01T23:59:00-05:00, or ...Z for UTC. */
char *time_format(double when, int zone)
{
    double local = floor(when) + 60.0 * zone;
    long days = (long)floor(local / 86400);
    long seconds = (long)(local - 86400.0 * days), y;
    int m, d, offset = zone < 0 ? -zone : zone;
    civil_from_days(days, &y, &m, &d);
    char *z = zone == 0 ? "Z" : grade_format("%c%02d:%02d", zone < 0 ? '-' : '+', offset / 60,
                                             offset % 60);
    return grade_format("%04ld-%02d-%02dT%02ld:%02ld:%02ld%s", y, m, d, seconds / 3600,
                        seconds / 60 % 60, seconds % 60, z);
}

/* Reads a duration: 0, or a number followed by s, m, h or d (90s, 15m, 2h, 1d), into
 * *seconds; false when the text is none, or negative. */
bool time_parse_duration(const char *text, double *seconds)
{
    static const char units[] = "smhd";
    static const double unit_seconds[] = {1, 60, 3600, 86400};
    char *end;
    double v = strtod(text, &end);
    const char *unit = end != text && end[0] != '\0' && end[1] == '\0' ? strchr(units, end[0])
                                                                      : NULL;
    if (end == text || !isfinite(v) || v < 0 || v > 1e6 ||
        (unit == NULL && !(*end == '\0' && v == 0)))
        return false;
    *seconds = unit != NULL ? v * unit_seconds[unit - units] : 0;
    return true;
}

/* Returns a duration in words, in the largest unit that gives it whole, else in minutes: "15
 * min", "2 h", "1 day", "36 h". */
char *time_duration_text(double seconds)
{
    if (seconds >= 86400 && fmod(seconds, 86400) == 0)
        return grade_format("%g day%s", seconds / 86400, seconds == 86400 ? "" : "s");
    if (seconds >= 3600 && fmod(seconds, 3600) == 0)
        return grade_format("%g h", seconds / 3600);
    if (seconds >= 60 && fmod(seconds, 60) == 0)
        return grade_format("%g min", seconds / 60);
    return grade_format("%g s", seconds);
}
