/*
 * The quasi-static catenary mooring law, inextensible and elastic, with a seabed.
 *
 * A C99 port (libm only) of moorings/catenary.py: the same one-parameter
 * reductions, the same state decisions and the same safeguarded Newton
 * iteration in the logarithm of the unknown, operation for operation, so that
 * the results agree with the Python law to rounding. Units: SI (m, N, N/m).
 *
 * Geometry: the anchor lies on a flat seabed; the fairlead is at horizontal
 * distance X [m] and height h [m] above it. The line has unstretched length
 * L [m], submerged weight w [N/m] per unit length and axial stiffness EA [N]
 * (INFINITY: inextensible).
 */
#ifndef MOORINGS_CATENARY_H
#define MOORINGS_CATENARY_H

/* Line states, as moorings.catenary.LineState. */
#define CAT_RESTING 0
#define CAT_PARTLY_LIFTED 1
#define CAT_FULLY_LIFTED 2
#define CAT_TAUT 3

/* The declarations are hidden from other shared objects when compiled with
 * -fvisibility=hidden, so two FMUs in one process never share these symbols. */
typedef struct {
    double H;         /* horizontal tension at the fairlead [N] */
    double V;         /* vertical tension at the fairlead [N] */
    double touchdown; /* unstretched length lying on the seabed [m] */
    int state;        /* CAT_RESTING .. CAT_TAUT */
} cat_solution;

/* 0 if the inputs are valid, else the number of the first bad one
 * (1 X, 2 h, 3 L, 4 w, 5 EA), as moorings.catenary._check. */
int cat_check(double X, double h, double L, double w, double EA);

/* Solve one line. Returns cat_check's code; out is written only when it is 0.
 * A taut inextensible line (EA = INFINITY, sqrt(X^2 + h^2) >= L) returns
 * H = V = INFINITY, touchdown 0 and CAT_TAUT, as the Python law does. */
int cat_solve(double X, double h, double L, double w, double EA, cat_solution *out);

/* X [m] of the inextensible lift-off point and of the taut point. */
double cat_lift_x(double h, double L);
double cat_taut_x(double h, double L);

#endif
