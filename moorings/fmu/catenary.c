/*
 * The quasi-static catenary mooring law: a line-by-line C99 port of
 * moorings/catenary.py (see its module docstring for the equations and the
 * one-parameter reductions). Internal units: lengths in L, forces in w L,
 * eps = w L / EA. Compile without -ffast-math and with -ffp-contract=off so
 * that every operation rounds as in the Python law.
 */
#include <math.h>

#include "catenary.h"

#define U_CAP 350.0 /* sinh(350) ~ 1e152: far from overflow, far past any physical angle */
#define LOG_T_CAP log(700.0) /* sinh(700) ~ 5e303 still finite */

/* Python's max(a, b) / min(a, b): the first argument unless the second is strictly larger / smaller. */
static double pmax(double a, double b) { return b > a ? b : a; }
static double pmin(double a, double b) { return b < a ? b : a; }

/* Seabed-contact regime at fairlead angle t: X, H, V, dX/dt. */
static void seabed(double t, double z, double eps, double *X, double *H, double *V, double *dX)
{
    double q = tanh(0.5 * t);
    double S = sqrt(q * q + 2.0 * eps * z);
    double v = 2.0 * z / (q + S);
    double st = sinh(t);
    double h = v / st;
    double dV = -v * (1.0 + q / S) / (q + S) * 0.5 * (1.0 - q * q);
    double dH = (dV - h * cosh(t)) / st;
    *X = 1.0 - v + h * t + eps * h;
    *H = h;
    *V = v;
    *dX = -dV + h + (t + eps) * dH;
}

/* Fully suspended regime at half angle range u: X, H, V, dX/du. */
static void suspended(double u, double z, double eps, double *X, double *H, double *V, double *dX)
{
    double tu = tanh(u);
    double a = tu + 0.5 * eps;
    double tau = z * tu / a; /* tanh m */
    double dtau = 0.5 * z * eps * (1.0 - tu * tu) / (a * a);
    double c = sqrt((1.0 - tau) * (1.0 + tau));
    double su = sinh(u);
    double h = c / (2.0 * su);
    double dH = (-0.5 * tau * dtau / c - h * cosh(u)) / su;
    *X = (2.0 * u + eps) * h;
    *H = h;
    *V = 0.5 + 0.5 * z / a;
    *dX = 2.0 * h + (2.0 * u + eps) * dH;
}

/* g(u) = 1 - u / sinh(u) and g'(u), without cancellation at small u. */
static void one_minus_sinhc(double u, double *g, double *dg)
{
    double s, u2, term, excess;
    int k;
    if (u >= 1.0) {
        s = sinh(u);
        *g = (s - u) / s;
        *dg = (u * cosh(u) - s) / (s * s);
        return;
    }
    u2 = u * u;
    term = u * u2 / 6.0; /* u^3/3! */
    excess = term;
    k = 1;
    while (term > 1e-17 * excess) {
        term *= u2 / ((2 * k + 2) * (2 * k + 3));
        excess += term;
        k += 1;
    }
    s = u + excess;
    *g = excess / s;
    *dg = (u2 * u / 3.0) * (1.0 + u2 / 10.0) / (s * s);
}

/* Residual of a regime at e^p and its derivative in p: X(e^p) - x for the seabed (0)
 * and suspended (1) regimes; 1 - u/sinh(u) - x for the inextensible suspended regime
 * near taut (2), where x is the relative gap to taut. */
static double f(int regime, double p, double z, double eps, double x, double *df)
{
    double t = exp(p), X, H, V, dX;
    if (regime == 2) {
        double g, dg;
        one_minus_sinhc(t, &g, &dg);
        if (df)
            *df = dg * t;
        return g - x;
    }
    if (regime == 0)
        seabed(t, z, eps, &X, &H, &V, &dX);
    else
        suspended(t, z, eps, &X, &H, &V, &dX);
    if (df)
        *df = dX * t;
    return X - x;
}

/* Safeguarded Newton on a bracket [a, b] with f(a) f(b) <= 0, in the log variable p. */
static double newton(int regime, double a, double b, double fa, double fb, double z, double eps, double x)
{
    double lo, hi, p, step, step_old, fp, df, p_prev;
    int it;
    if (fa == 0.0)
        return a;
    if (fb == 0.0)
        return b;
    if ((fa > 0.0) == (fb > 0.0))
        return fabs(fa) < fabs(fb) ? a : b;
    if (fa < 0.0) { /* f(lo) < 0 < f(hi) */
        lo = a;
        hi = b;
    } else {
        lo = b;
        hi = a;
    }
    p = a - fa * (b - a) / (fb - fa);
    step = step_old = fabs(b - a);
    fp = f(regime, p, z, eps, x, &df);
    for (it = 0; it < 100; it++) {
        if (((p - hi) * df - fp) * ((p - lo) * df - fp) > 0.0 || fabs(2.0 * fp) > fabs(step_old * df)) {
            step_old = step;
            step = 0.5 * (hi - lo);
            p = lo + step;
            if (p == lo)
                return p;
        } else {
            step_old = step;
            step = fp / df;
            p_prev = p;
            p -= step;
            if (p == p_prev)
                return p;
        }
        if (fabs(step) < 1e-14 * pmax(1.0, fabs(p)))
            return p;
        fp = f(regime, p, z, eps, x, &df);
        if (fp < 0.0)
            lo = p;
        else
            hi = p;
    }
    return p;
}

double cat_taut_x(double h, double L)
{
    return h < L ? sqrt((L - h) * (L + h)) : 0.0;
}

double cat_lift_x(double h, double L)
{
    double r;
    if (h <= 0.0)
        return L;
    r = h / L;
    return (L - h) * (L + h) / L * (atanh(r) / r);
}

/* Unknown t of the seabed regime, between lift-off and the resting point. */
static double seabed_root(double x, double z, double eps, double d, double u_lift)
{
    double a, fa, b, fb;
    if (d > 0.0) {
        a = log(2.0 * u_lift); /* the lift-off angle */
        fa = f(0, a, z, eps, x, 0);
    } else {
        a = log(sqrt(2.0 * z * eps) / x) - 1.0;
        fa = f(0, a, z, eps, x, 0);
        while (fa < 0.0 && a > -700.0) {
            a -= 2.0;
            fa = f(0, a, z, eps, x, 0);
        }
    }
    b = pmax(a + 1.0, 1.0);
    fb = f(0, b, z, eps, x, 0);
    while (fb > 0.0 && b < LOG_T_CAP) {
        a = b;
        fa = fb;
        b = pmin(b + 1.0, LOG_T_CAP);
        fb = f(0, b, z, eps, x, 0);
    }
    return exp(newton(0, a, b, fa, fb, z, eps, x));
}

/* Unknown u of the elastic fully suspended regime, in (0, u_max]; X(u) decreases. */
static double suspended_root(double x, double z, double eps, double u_max)
{
    double a, fa, b, fb;
    b = log(u_max);
    fb = f(1, b, z, eps, x, 0);
    a = pmin(log(0.25 * eps / pmax(x, 1e-300)), b - 1.0); /* X ~ 1 + eps / 2u there */
    fa = f(1, a, z, eps, x, 0);
    while (fa < 0.0 && a > -700.0) {
        b = a;
        fb = fa;
        a -= 2.0;
        fa = f(1, a, z, eps, x, 0);
    }
    return exp(newton(1, a, b, fa, fb, z, eps, x));
}

/* Unknown u of the inextensible fully suspended regime: 1 - u/sinh(u) = gap, with
 * gap = 1 - X/X_taut > 0 from the dimensional values (finite even one ulp below taut). */
static double taut_gap_root(double gap, double u_lift)
{
    double a, fa, b, fb;
    b = log(u_lift);
    fb = f(2, b, 0.0, 0.0, gap, 0);
    a = pmin(0.5 * log(6.0 * gap) - 1.0, b - 1.0); /* 1 - u/sinh(u) ~ u^2/6 */
    fa = f(2, a, 0.0, 0.0, gap, 0);
    while (fa > 0.0 && a > -700.0) {
        b = a;
        fb = fa;
        a -= 2.0;
        fa = f(2, a, 0.0, 0.0, gap, 0);
    }
    return exp(newton(2, a, b, fa, fb, 0.0, 0.0, gap));
}

static void put(cat_solution *out, double H, double V, double td, int state)
{
    out->H = H;
    out->V = V;
    out->touchdown = td;
    out->state = state;
}

/* One line, inputs already checked (moorings.catenary._solve_dim). */
static void solve_dim(double X, double h, double L, double w, double EA, cat_solution *out)
{
    double ls, wl, eps, x, z, d, u_lift, x_lift, u_max, Xr, H, V, dX;
    int taut;
    /* RESTING: straight down, hanging length l_s with l_s (1 + w l_s / 2 EA) = h */
    ls = 2.0 * h / (1.0 + sqrt(1.0 + 2.0 * w * h / EA));
    if (ls <= L && X <= L - ls) {
        put(out, 0.0, w * ls, L - ls, CAT_RESTING);
        return;
    }
    taut = X >= cat_taut_x(h, L);
    wl = w * L;
    eps = wl / EA;
    x = X / L;
    z = h / L;
    if (eps == 0.0) {
        double X_lift;
        if (taut) {
            put(out, INFINITY, INFINITY, 0.0, CAT_TAUT);
            return;
        }
        X_lift = cat_lift_x(h, L);
        if (X == X_lift) { /* exactly at lift-off: Eq. 37 with l_s = L */
            put(out, w * (L - h) * (L + h) / (2.0 * h), wl, 0.0, CAT_FULLY_LIFTED);
            return;
        }
        if (X < X_lift) {
            seabed(seabed_root(x, z, 0.0, z, atanh(z)), z, 0.0, &Xr, &H, &V, &dX);
            put(out, H * wl, V * wl, pmax(1.0 - V, 0.0) * L, CAT_PARTLY_LIFTED);
            return;
        }
        {
            double X_taut = cat_taut_x(h, L);
            suspended(taut_gap_root((X_taut - X) / X_taut, atanh(z)), z, 0.0, &Xr, &H, &V, &dX);
        }
        put(out, H * wl, V * wl, 0.0, CAT_FULLY_LIFTED);
        return;
    }
    if (h == 0.0) { /* flat on the seabed and stretched */
        put(out, EA * (x - 1.0), 0.0, L, CAT_TAUT);
        return;
    }
    d = z - 0.5 * eps; /* tanh of the half angle range at lift-off */
    if (0.0 < d && d < 1.0) {
        u_lift = atanh(d);
        suspended(u_lift, z, eps, &x_lift, &H, &V, &dX);
    } else {
        u_lift = U_CAP;
        x_lift = d <= 0.0 ? INFINITY : 0.0;
    }
    if (x < x_lift) {
        seabed(seabed_root(x, z, eps, d, u_lift), z, eps, &Xr, &H, &V, &dX);
        put(out, H * wl, V * wl, pmax(1.0 - V, 0.0) * L, taut ? CAT_TAUT : CAT_PARTLY_LIFTED);
        return;
    }
    if (d >= 1.0) /* hangs clear of the seabed at any X; X -> 0 as tanh m -> 1 */
        u_max = pmin(atanh(pmin(0.5 * eps / (z - 1.0), 1.0)), U_CAP);
    else
        u_max = u_lift;
    suspended(suspended_root(x, z, eps, u_max), z, eps, &Xr, &H, &V, &dX);
    put(out, H * wl, V * wl, 0.0, taut ? CAT_TAUT : CAT_FULLY_LIFTED);
}

int cat_check(double X, double h, double L, double w, double EA)
{
    if (!(isfinite(X) && X >= 0.0))
        return 1;
    if (!(isfinite(h) && h >= 0.0))
        return 2;
    if (!(isfinite(L) && L > 0.0))
        return 3;
    if (!(isfinite(w) && w > 0.0))
        return 4;
    if (!(EA > 0.0)) /* inf is allowed: inextensible */
        return 5;
    return 0;
}

int cat_solve(double X, double h, double L, double w, double EA, cat_solution *out)
{
    int err = cat_check(X, h, L, w, EA);
    if (err)
        return err;
    solve_dim(X, h, L, w, EA, out);
    return 0;
}
