/*
 * FMI 2.0 co-simulation interface of a catenary mooring system.
 *
 * Inputs are the fairlead positions; outputs the force each line exerts on its
 * fairlead (world frame), the total force and its moment about a reference
 * point, and each line's fairlead tension, H, V, touchdown length and state.
 * The law (catenary.c) is quasi-static, hence stateless: the outputs are a pure
 * function of the parameters and inputs, evaluated whenever one of them changed
 * (direct feedthrough), and fmi2DoStep only moves the clock. The FMU state that
 * fmi2GetFMUstate copies is therefore all variable values plus the time.
 *
 * The system's size and the start values come from model_config.h, written by
 * moorings/fmu_export.py: N_LINES, DIM (2: x, z; 3: x, y, z), MODEL_GUID,
 * START_VALUES[N_REAL] and LINE_NAMES[N_LINES]. Value references (Real):
 *   0 .. DIM-1                    reference point of the total moment [m]
 *   LINE_BASE(i) + O_ANCHOR + k   anchor of line i [m] (its last coordinate is
 *                                 the seabed height: the seabed is the
 *                                 horizontal plane through the anchor)
 *   LINE_BASE(i) + O_LENGTH       unstretched length [m]
 *   LINE_BASE(i) + O_WEIGHT       submerged weight per unit length [N/m]
 *   LINE_BASE(i) + O_EA           axial stiffness [N]; 0 = inextensible
 *   LINE_BASE(i) + O_FAIR + k     fairlead position (input) [m]
 *   LINE_BASE(i) + O_FORCE + k    force on the fairlead (output) [N]
 *   LINE_BASE(i) + O_TENSION, O_H, O_V, O_TD   outputs [N, N, N, m]
 *   VR_FTOT + k, VR_MOM + k       total force [N], moment [N m] (2-D: about y)
 * Integer: VR_STATE + i, the state of line i (0 resting, 1 partly lifted,
 * 2 fully lifted, 3 taut).
 *
 * With BODY_POSE defined to 1 the fairleads follow a rigid body: the pose is
 * the input (VR_POSE: 3-D x, y, z [m] and a unit quaternion qw, qx, qy, qz
 * [-], normalised here; 2-D x, z [m] and the pitch angle theta [rad] about +y),
 * the body-frame fairlead coordinates are parameters (VR_FB + i DIM + k) [m],
 * the world-frame fairlead positions become outputs, and the reference point
 * of the moment is given in the body frame.
 *
 * Errors (an invalid parameter, a NaN input, a fairlead below the seabed, a
 * taut inextensible line) are reported through the logger and an fmi2Error
 * status; the host decides what to do, nothing aborts.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "fmi2Functions.h"

#include "catenary.h"
#include "model_config.h"

#define LINE_STRIDE (3 * DIM + 7)
#define O_ANCHOR 0
#define O_LENGTH DIM
#define O_WEIGHT (DIM + 1)
#define O_EA (DIM + 2)
#define O_FAIR (DIM + 3)
#define O_FORCE (2 * DIM + 3)
#define O_TENSION (3 * DIM + 3)
#define O_H (3 * DIM + 4)
#define O_V (3 * DIM + 5)
#define O_TD (3 * DIM + 6)
#define LINE_BASE(i) (DIM + (i) * LINE_STRIDE)
#define VR_FTOT (DIM + N_LINES * LINE_STRIDE)
#define VR_MOM (VR_FTOT + DIM)
#define N_MOM (DIM == 3 ? 3 : 1)
#ifndef BODY_POSE
#define BODY_POSE 0
#endif
#define VR_FB (VR_MOM + N_MOM)
#define VR_POSE (VR_FB + (BODY_POSE ? N_LINES * DIM : 0))
#define N_POSE (BODY_POSE ? (DIM == 3 ? 7 : 3) : 0)
#define N_REAL_LAYOUT (VR_POSE + N_POSE)
#define VR_STATE N_REAL

typedef char layout_matches_config[(N_REAL_LAYOUT == N_REAL) ? 1 : -1];

enum { MODE_INSTANTIATED, MODE_INIT, MODE_STEP, MODE_TERMINATED };

typedef struct { /* everything that defines the instance's state */
    double time;
    double r[N_REAL];
    int state[N_LINES];
    int mode;
    int dirty;          /* outputs must be recomputed */
    fmi2Status outcome; /* status of the last evaluation */
} snapshot;

typedef struct {
    const fmi2CallbackFunctions *cb;
    char name[128];
    int logging_on;
    snapshot s;
} instance;

static void logmsg(instance *c, fmi2Status status, const char *category, const char *fmt, ...)
{
    char buf[1024];
    va_list ap;
    if (!c->cb || !c->cb->logger)
        return;
    if (status == fmi2OK && !c->logging_on)
        return;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    c->cb->logger(c->cb->componentEnvironment, c->name, status, category, "%s", buf);
}

static int is_parameter(fmi2ValueReference vr)
{
    if (vr < DIM)
        return 1;
    if (vr < VR_FTOT)
        return (vr - DIM) % LINE_STRIDE < O_FAIR;
    return BODY_POSE && vr >= VR_FB && vr < VR_POSE;
}

static int is_input(fmi2ValueReference vr)
{
    unsigned k;
    if (BODY_POSE)
        return vr >= VR_POSE && vr < VR_POSE + N_POSE;
    if (vr < DIM || vr >= VR_FTOT)
        return 0;
    k = (vr - DIM) % LINE_STRIDE;
    return k >= O_FAIR && k < O_FAIR + DIM;
}

/* Body pose mode: world fairleads = p + R r_b; the reference point likewise.
 * Returns 0, or 1 for a quaternion of zero length. */
static int place_fairleads(double *r, double ref[3])
{
    const double *P = r + VR_POSE;
    double R[3][3];
    int i, j, k;
    if (DIM == 3) {
        double w = P[3], x = P[4], y = P[5], z = P[6], n = sqrt(w * w + x * x + y * y + z * z);
        if (!(n > 0.0))
            return 1;
        w /= n;
        x /= n;
        y /= n;
        z /= n;
        R[0][0] = 1.0 - 2.0 * (y * y + z * z);
        R[0][1] = 2.0 * (x * y - w * z);
        R[0][2] = 2.0 * (x * z + w * y);
        R[1][0] = 2.0 * (x * y + w * z);
        R[1][1] = 1.0 - 2.0 * (x * x + z * z);
        R[1][2] = 2.0 * (y * z - w * x);
        R[2][0] = 2.0 * (x * z - w * y);
        R[2][1] = 2.0 * (y * z + w * x);
        R[2][2] = 1.0 - 2.0 * (x * x + y * y);
    } else { /* (x, z) rotated by theta about +y: x' = c x + s z, z' = -s x + c z */
        double c = cos(P[2]), s = sin(P[2]);
        R[0][0] = c;
        R[0][1] = s;
        R[1][0] = -s;
        R[1][1] = c;
    }
    for (i = 0; i <= N_LINES; i++) {
        const double *b = i < N_LINES ? r + VR_FB + i * DIM : r; /* the last one: the reference point */
        double *out = i < N_LINES ? r + LINE_BASE(i) + O_FAIR : ref;
        for (j = 0; j < DIM; j++) {
            double acc = P[j];
            for (k = 0; k < DIM; k++)
                acc += R[j][k] * b[k];
            out[j] = acc;
        }
    }
    return 0;
}

static const char *axis(int k) { return DIM == 2 ? (k == 0 ? "x" : "z") : (k == 0 ? "x" : k == 1 ? "y" : "z"); }

/* Evaluate every line; the first error is logged and returned, the rest solved. */
static fmi2Status evaluate(instance *c)
{
    double *r = c->s.r, ftot[3] = {0, 0, 0}, mom[3] = {0, 0, 0}, ref[3] = {0, 0, 0};
    fmi2Status status = fmi2OK;
    int i, k;
    for (k = 0; k < DIM; k++)
        ref[k] = r[k];
    if (BODY_POSE && place_fairleads(r, ref)) {
        logmsg(c, fmi2Error, "logStatusError", "the body orientation quaternion has zero length");
        status = fmi2Error;
    }
    for (i = 0; i < N_LINES; i++) {
        double *p = r + LINE_BASE(i), d[3], X2 = 0.0, X, h, EA;
        cat_solution sol;
        int err;
        const char *bad = NULL;
        for (k = 0; k < DIM; k++)
            if (!isfinite(p[O_ANCHOR + k]))
                bad = "the anchor coordinates must be finite [m]";
        if (!(isfinite(p[O_LENGTH]) && p[O_LENGTH] > 0.0))
            bad = "the unstretched length must be finite and > 0 [m]";
        else if (!(isfinite(p[O_WEIGHT]) && p[O_WEIGHT] > 0.0))
            bad = "the submerged weight per unit length must be finite and > 0 [N/m]";
        else if (!(p[O_EA] >= 0.0))
            bad = "EA must be > 0 [N], or 0 for an inextensible line";
        for (k = 0; k < DIM; k++)
            if (!isfinite(p[O_FAIR + k]))
                bad = "the fairlead position is not finite (NaN or infinite input)";
        for (k = 0; k < DIM; k++)
            d[k] = p[O_FAIR + k] - p[O_ANCHOR + k];
        h = d[DIM - 1];
        if (!bad && h < 0.0)
            bad = "the fairlead is below the seabed through its anchor; move the anchor down or the fairlead up";
        if (bad) {
            if (status == fmi2OK)
                logmsg(c, fmi2Error, "logStatusError", "line '%s': %s", LINE_NAMES[i], bad);
            status = fmi2Error;
            for (k = 0; k < DIM; k++)
                p[O_FORCE + k] = NAN;
            p[O_TENSION] = p[O_H] = p[O_V] = p[O_TD] = NAN;
            c->s.state[i] = -1;
            continue;
        }
        for (k = 0; k < DIM - 1; k++)
            X2 += d[k] * d[k];
        X = sqrt(X2);
        EA = p[O_EA] == 0.0 || isinf(p[O_EA]) ? INFINITY : p[O_EA];
        err = cat_solve(X, h, p[O_LENGTH], p[O_WEIGHT], EA, &sol);
        if (err || isnan(sol.H) || isnan(sol.V)) {
            if (status == fmi2OK)
                logmsg(c, fmi2Error, "logStatusError", "line '%s': no catenary solution for X = %.17g m, h = %.17g m",
                       LINE_NAMES[i], X, h);
            status = fmi2Error;
            sol.H = sol.V = sol.touchdown = NAN;
            sol.state = -1;
        } else if (isinf(sol.H)) {
            if (status == fmi2OK)
                logmsg(c, fmi2Error, "logStatusError",
                       "line '%s': the inextensible line of length %.6g m would have to span %.6g m "
                       "(X = %.6g m, h = %.6g m); no catenary exists (taut line). Give the line an axial "
                       "stiffness EA, lengthen it, or limit the fairlead's offset.",
                       LINE_NAMES[i], p[O_LENGTH], hypot(X, h), X, h);
            status = fmi2Error;
        }
        for (k = 0; k < DIM - 1; k++)
            p[O_FORCE + k] = X > 0.0 ? -sol.H * (d[k] / X) : 0.0;
        p[O_FORCE + DIM - 1] = -sol.V;
        p[O_TENSION] = hypot(sol.H, sol.V);
        p[O_H] = sol.H;
        p[O_V] = sol.V;
        p[O_TD] = sol.touchdown;
        c->s.state[i] = sol.state;
        for (k = 0; k < DIM; k++)
            ftot[k] += p[O_FORCE + k];
        if (DIM == 3) {
            double rr[3], *fo = p + O_FORCE;
            for (k = 0; k < 3; k++)
                rr[k] = p[O_FAIR + k] - ref[k];
            mom[0] += rr[1] * fo[2] - rr[2] * fo[1];
            mom[1] += rr[2] * fo[0] - rr[0] * fo[2];
            mom[2] += rr[0] * fo[1] - rr[1] * fo[0];
        } else { /* about y in the x-z plane: M_y = r_z F_x - r_x F_z */
            mom[0] += (p[O_FAIR + 1] - ref[1]) * p[O_FORCE] - (p[O_FAIR] - ref[0]) * p[O_FORCE + 1];
        }
    }
    for (k = 0; k < DIM; k++)
        r[VR_FTOT + k] = ftot[k];
    for (k = 0; k < N_MOM; k++)
        r[VR_MOM + k] = mom[k];
    c->s.dirty = 0;
    c->s.outcome = status;
    return status;
}

static fmi2Status refresh(instance *c)
{
    return c->s.dirty ? evaluate(c) : c->s.outcome;
}

static void set_start_values(instance *c)
{
    memcpy(c->s.r, START_VALUES, sizeof c->s.r);
    memset(c->s.state, 0, sizeof c->s.state);
    c->s.time = 0.0;
    c->s.mode = MODE_INSTANTIATED;
    c->s.dirty = 1;
    c->s.outcome = fmi2OK;
}

/* ---- inquire version numbers, logging -------------------------------------------------- */

FMI2_Export const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
FMI2_Export const char *fmi2GetVersion(void) { return fmi2Version; }

FMI2_Export fmi2Status fmi2SetDebugLogging(fmi2Component comp, fmi2Boolean loggingOn, size_t nCategories,
                                           const fmi2String categories[])
{
    (void)nCategories;
    (void)categories;
    if (!comp)
        return fmi2Error;
    ((instance *)comp)->logging_on = loggingOn ? 1 : 0;
    return fmi2OK;
}

/* ---- creation and destruction ------------------------------------------------------------ */

FMI2_Export fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                                          fmi2String fmuResourceLocation, const fmi2CallbackFunctions *functions,
                                          fmi2Boolean visible, fmi2Boolean loggingOn)
{
    instance tmp, *c;
    (void)fmuResourceLocation;
    (void)visible;
    memset(&tmp, 0, sizeof tmp);
    tmp.cb = functions;
    snprintf(tmp.name, sizeof tmp.name, "%s", instanceName ? instanceName : "?");
    if (!functions || !functions->allocateMemory || !functions->freeMemory) {
        logmsg(&tmp, fmi2Error, "logStatusError", "fmi2Instantiate: allocateMemory and freeMemory are required");
        return NULL;
    }
    if (fmuType != fmi2CoSimulation) {
        logmsg(&tmp, fmi2Error, "logStatusError", "fmi2Instantiate: this FMU supports co-simulation only");
        return NULL;
    }
    if (!fmuGUID || strcmp(fmuGUID, MODEL_GUID) != 0) {
        logmsg(&tmp, fmi2Error, "logStatusError", "fmi2Instantiate: GUID %s does not match this binary's %s",
               fmuGUID ? fmuGUID : "(null)", MODEL_GUID);
        return NULL;
    }
    c = (instance *)functions->allocateMemory(1, sizeof(instance));
    if (!c) {
        logmsg(&tmp, fmi2Error, "logStatusError", "fmi2Instantiate: out of memory");
        return NULL;
    }
    *c = tmp;
    c->logging_on = loggingOn ? 1 : 0;
    set_start_values(c);
    return c;
}

FMI2_Export void fmi2FreeInstance(fmi2Component comp)
{
    instance *c = (instance *)comp;
    if (c)
        c->cb->freeMemory(c);
}

/* ---- initialisation, termination, reset --------------------------------------------------- */

FMI2_Export fmi2Status fmi2SetupExperiment(fmi2Component comp, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                                           fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime)
{
    instance *c = (instance *)comp;
    (void)toleranceDefined;
    (void)tolerance;
    (void)stopTimeDefined;
    (void)stopTime;
    if (!c)
        return fmi2Error;
    if (c->s.mode != MODE_INSTANTIATED) {
        logmsg(c, fmi2Error, "logStatusError", "fmi2SetupExperiment: only allowed after fmi2Instantiate or fmi2Reset");
        return fmi2Error;
    }
    c->s.time = startTime;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2EnterInitializationMode(fmi2Component comp)
{
    instance *c = (instance *)comp;
    if (!c)
        return fmi2Error;
    if (c->s.mode != MODE_INSTANTIATED) {
        logmsg(c, fmi2Error, "logStatusError", "fmi2EnterInitializationMode: not after fmi2Instantiate/fmi2Reset");
        return fmi2Error;
    }
    c->s.mode = MODE_INIT;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2ExitInitializationMode(fmi2Component comp)
{
    instance *c = (instance *)comp;
    if (!c)
        return fmi2Error;
    if (c->s.mode != MODE_INIT) {
        logmsg(c, fmi2Error, "logStatusError", "fmi2ExitInitializationMode: not in initialization mode");
        return fmi2Error;
    }
    c->s.mode = MODE_STEP;
    return refresh(c); /* bad parameters or a taut start are reported before any step */
}

FMI2_Export fmi2Status fmi2Terminate(fmi2Component comp)
{
    instance *c = (instance *)comp;
    if (!c)
        return fmi2Error;
    c->s.mode = MODE_TERMINATED;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2Reset(fmi2Component comp)
{
    instance *c = (instance *)comp;
    if (!c)
        return fmi2Error;
    set_start_values(c);
    return fmi2OK;
}

/* ---- getting and setting values ----------------------------------------------------------- */

static fmi2Status bad_vr(instance *c, const char *fn, fmi2ValueReference vr)
{
    logmsg(c, fmi2Error, "logStatusError", "%s: unknown value reference %u", fn, (unsigned)vr);
    return fmi2Error;
}

FMI2_Export fmi2Status fmi2GetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr, fmi2Real value[])
{
    instance *c = (instance *)comp;
    fmi2Status status;
    size_t i;
    if (!c)
        return fmi2Error;
    for (i = 0; i < nvr; i++)
        if (vr[i] >= N_REAL)
            return bad_vr(c, "fmi2GetReal", vr[i]);
    status = refresh(c);
    for (i = 0; i < nvr; i++)
        value[i] = c->s.r[vr[i]];
    return status;
}

FMI2_Export fmi2Status fmi2GetInteger(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                                      fmi2Integer value[])
{
    instance *c = (instance *)comp;
    fmi2Status status;
    size_t i;
    if (!c)
        return fmi2Error;
    for (i = 0; i < nvr; i++)
        if (vr[i] < VR_STATE || vr[i] >= VR_STATE + N_LINES)
            return bad_vr(c, "fmi2GetInteger", vr[i]);
    status = refresh(c);
    for (i = 0; i < nvr; i++)
        value[i] = c->s.state[vr[i] - VR_STATE];
    return status;
}

FMI2_Export fmi2Status fmi2GetBoolean(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                                      fmi2Boolean value[])
{
    (void)value;
    return nvr ? bad_vr((instance *)comp, "fmi2GetBoolean", vr[0]) : fmi2OK;
}

FMI2_Export fmi2Status fmi2GetString(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                                     fmi2String value[])
{
    (void)value;
    return nvr ? bad_vr((instance *)comp, "fmi2GetString", vr[0]) : fmi2OK;
}

FMI2_Export fmi2Status fmi2SetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                                   const fmi2Real value[])
{
    instance *c = (instance *)comp;
    size_t i;
    if (!c)
        return fmi2Error;
    if (c->s.mode == MODE_TERMINATED) {
        logmsg(c, fmi2Error, "logStatusError", "fmi2SetReal: the instance is terminated; call fmi2Reset");
        return fmi2Error;
    }
    for (i = 0; i < nvr; i++) { /* check everything before changing anything */
        if (vr[i] >= N_REAL)
            return bad_vr(c, "fmi2SetReal", vr[i]);
        if (!is_parameter(vr[i]) && !is_input(vr[i])) {
            logmsg(c, fmi2Error, "logStatusError", "fmi2SetReal: value reference %u is an output", (unsigned)vr[i]);
            return fmi2Error;
        }
        if (isnan(value[i])) {
            if (is_input(vr[i])) {
                if (BODY_POSE) {
                    logmsg(c, fmi2Error, "logStatusError", "fmi2SetReal: body pose component %u is NaN",
                           (unsigned)(vr[i] - VR_POSE));
                } else {
                    unsigned k = (vr[i] - DIM) % LINE_STRIDE - O_FAIR;
                    logmsg(c, fmi2Error, "logStatusError", "fmi2SetReal: line '%s': fairlead %s is NaN",
                           LINE_NAMES[(vr[i] - DIM) / LINE_STRIDE], axis((int)k));
                }
            } else {
                logmsg(c, fmi2Error, "logStatusError", "fmi2SetReal: parameter (value reference %u) is NaN",
                       (unsigned)vr[i]);
            }
            return fmi2Error;
        }
    }
    for (i = 0; i < nvr; i++)
        c->s.r[vr[i]] = value[i];
    if (nvr)
        c->s.dirty = 1;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2SetInteger(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                                      const fmi2Integer value[])
{
    (void)vr;
    (void)value;
    if (!nvr)
        return fmi2OK;
    logmsg((instance *)comp, fmi2Error, "logStatusError", "fmi2SetInteger: the line states are outputs");
    return fmi2Error;
}

FMI2_Export fmi2Status fmi2SetBoolean(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                                      const fmi2Boolean value[])
{
    (void)value;
    return nvr ? bad_vr((instance *)comp, "fmi2SetBoolean", vr[0]) : fmi2OK;
}

FMI2_Export fmi2Status fmi2SetString(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                                     const fmi2String value[])
{
    (void)value;
    return nvr ? bad_vr((instance *)comp, "fmi2SetString", vr[0]) : fmi2OK;
}

/* ---- FMU state: all values and the time (the law itself is stateless) ---------------------- */

FMI2_Export fmi2Status fmi2GetFMUstate(fmi2Component comp, fmi2FMUstate *FMUstate)
{
    instance *c = (instance *)comp;
    snapshot *s;
    if (!c || !FMUstate)
        return fmi2Error;
    s = (snapshot *)*FMUstate;
    if (!s) {
        s = (snapshot *)c->cb->allocateMemory(1, sizeof(snapshot));
        if (!s) {
            logmsg(c, fmi2Error, "logStatusError", "fmi2GetFMUstate: out of memory");
            return fmi2Error;
        }
    }
    *s = c->s;
    *FMUstate = s;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2SetFMUstate(fmi2Component comp, fmi2FMUstate FMUstate)
{
    instance *c = (instance *)comp;
    if (!c || !FMUstate)
        return fmi2Error;
    c->s = *(const snapshot *)FMUstate;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2FreeFMUstate(fmi2Component comp, fmi2FMUstate *FMUstate)
{
    instance *c = (instance *)comp;
    if (!c || !FMUstate)
        return fmi2Error;
    if (*FMUstate)
        c->cb->freeMemory(*FMUstate);
    *FMUstate = NULL;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2SerializedFMUstateSize(fmi2Component comp, fmi2FMUstate FMUstate, size_t *size)
{
    (void)comp;
    (void)FMUstate;
    *size = sizeof(snapshot) + sizeof MODEL_GUID;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2SerializeFMUstate(fmi2Component comp, fmi2FMUstate FMUstate, fmi2Byte serializedState[],
                                             size_t size)
{
    instance *c = (instance *)comp;
    if (!c || !FMUstate)
        return fmi2Error;
    if (size < sizeof(snapshot) + sizeof MODEL_GUID) {
        logmsg(c, fmi2Error, "logStatusError", "fmi2SerializeFMUstate: buffer too small");
        return fmi2Error;
    }
    memcpy(serializedState, MODEL_GUID, sizeof MODEL_GUID); /* so a foreign state is refused */
    memcpy(serializedState + sizeof MODEL_GUID, FMUstate, sizeof(snapshot));
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2DeSerializeFMUstate(fmi2Component comp, const fmi2Byte serializedState[], size_t size,
                                               fmi2FMUstate *FMUstate)
{
    instance *c = (instance *)comp;
    snapshot *s;
    if (!c || !FMUstate)
        return fmi2Error;
    if (size != sizeof(snapshot) + sizeof MODEL_GUID || memcmp(serializedState, MODEL_GUID, sizeof MODEL_GUID)) {
        logmsg(c, fmi2Error, "logStatusError", "fmi2DeSerializeFMUstate: not a state of this FMU");
        return fmi2Error;
    }
    s = (snapshot *)*FMUstate;
    if (!s)
        s = (snapshot *)c->cb->allocateMemory(1, sizeof(snapshot));
    if (!s) {
        logmsg(c, fmi2Error, "logStatusError", "fmi2DeSerializeFMUstate: out of memory");
        return fmi2Error;
    }
    memcpy(s, serializedState + sizeof MODEL_GUID, sizeof(snapshot));
    *FMUstate = s;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2GetDirectionalDerivative(fmi2Component comp, const fmi2ValueReference vUnknown_ref[],
                                                    size_t nUnknown, const fmi2ValueReference vKnown_ref[],
                                                    size_t nKnown, const fmi2Real dvKnown[], fmi2Real dvUnknown[])
{
    (void)vUnknown_ref;
    (void)nUnknown;
    (void)vKnown_ref;
    (void)nKnown;
    (void)dvKnown;
    (void)dvUnknown;
    logmsg((instance *)comp, fmi2Error, "logStatusError", "fmi2GetDirectionalDerivative: not provided");
    return fmi2Error;
}

/* ---- co-simulation ------------------------------------------------------------------------ */

FMI2_Export fmi2Status fmi2SetRealInputDerivatives(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                                                   const fmi2Integer order[], const fmi2Real value[])
{
    (void)vr;
    (void)nvr;
    (void)order;
    (void)value;
    logmsg((instance *)comp, fmi2Error, "logStatusError", "fmi2SetRealInputDerivatives: inputs are not interpolated");
    return fmi2Error;
}

FMI2_Export fmi2Status fmi2GetRealOutputDerivatives(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                                                    const fmi2Integer order[], fmi2Real value[])
{
    (void)vr;
    (void)nvr;
    (void)order;
    (void)value;
    logmsg((instance *)comp, fmi2Error, "logStatusError", "fmi2GetRealOutputDerivatives: not provided");
    return fmi2Error;
}

FMI2_Export fmi2Status fmi2DoStep(fmi2Component comp, fmi2Real currentCommunicationPoint,
                                  fmi2Real communicationStepSize, fmi2Boolean noSetFMUStatePriorToCurrentPoint)
{
    instance *c = (instance *)comp;
    fmi2Status status;
    (void)noSetFMUStatePriorToCurrentPoint;
    if (!c)
        return fmi2Error;
    if (c->s.mode != MODE_STEP) {
        logmsg(c, fmi2Error, "logStatusError", "fmi2DoStep: call fmi2ExitInitializationMode first");
        return fmi2Error;
    }
    if (!(communicationStepSize >= 0.0)) {
        logmsg(c, fmi2Error, "logStatusError", "fmi2DoStep: step size %g s must be >= 0", communicationStepSize);
        return fmi2Error;
    }
    status = refresh(c); /* quasi-static: the outputs follow the inputs */
    if (status == fmi2OK)
        c->s.time = currentCommunicationPoint + communicationStepSize;
    return status;
}

FMI2_Export fmi2Status fmi2CancelStep(fmi2Component comp)
{
    (void)comp;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2GetStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Status *value)
{
    (void)comp;
    (void)s;
    *value = fmi2OK;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2GetRealStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Real *value)
{
    instance *c = (instance *)comp;
    if (!c || s != fmi2LastSuccessfulTime)
        return fmi2Discard;
    *value = c->s.time;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2GetIntegerStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Integer *value)
{
    (void)comp;
    (void)s;
    (void)value;
    return fmi2Discard;
}

FMI2_Export fmi2Status fmi2GetBooleanStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Boolean *value)
{
    instance *c = (instance *)comp;
    if (!c || s != fmi2Terminated)
        return fmi2Discard;
    *value = fmi2False;
    return fmi2OK;
}

FMI2_Export fmi2Status fmi2GetStringStatus(fmi2Component comp, const fmi2StatusKind s, fmi2String *value)
{
    (void)comp;
    (void)s;
    (void)value;
    return fmi2Discard;
}
