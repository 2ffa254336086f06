/* statt.h: Student's t law and the normal law's tails, for the bias test's p-values. */
#ifndef RAYTRA_STATT_H
#define RAYTRA_STATT_H

double statt_two_sided(double t, double df);
double statt_normal_z(double p);

#endif
