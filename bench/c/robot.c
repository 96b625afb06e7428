/* The C side of the side-by-side benchmark (bench/run, bench/pinocchio/bench.cpp): one robot's
 * header of `dynamics emit --lang c` behind the functions of bench/ffi's C ABI, so that the C++
 * program times the C beside Pinocchio and the Rust, through the same kind of call.
 *
 * Compiled as C99 (gcc -std=c99), not included in bench.cpp: the header's functions are then
 * compiled as a C user compiles them, and g++'s treatment of the header as C++ is left out.
 * bench/run compiles this file once per robot, each into its own object (two robots may share a
 * prefix: the reference UR5 and the UR5 of the URDF are both `ur5`), and links them into one
 * shared library that the C++ program loads as it loads bench/ffi's, so that both sides are
 * called through a pointer into position-independent code. Defines, from bench/run:
 *
 *   DYNAMICS_HEADER  the header, e.g. "puma560.h"
 *   PREFIX           its functions' prefix, e.g. puma560
 *   NAME             the robot's name in the benchmark, e.g. ur5_urdf
 *   DOF              its number of joints
 *   BASE             its number of base parameters
 *
 * The one exported function, dynamics_bench_c_NAME(function), returns the function named as
 * bench/ffi names it (tau, M, g, C, h, fk, J, JtF, fd, Minv, dtau, dqdd, Y, YB, piB), with
 * bench/ffi's signature and output layout, or NULL. As bench/ffi does, a solve whose M is not
 * positive definite (a status of 1) writes NaN. */

#include DYNAMICS_HEADER

#include <math.h>
#include <string.h>

#define JOIN_(a, b) a##_##b
#define JOIN(a, b) JOIN_(a, b)
/* The header's function of method m: PREFIX_m. */
#define METHOD(m) JOIN(PREFIX, m)

typedef void (*function)(const double *, const double *, const double *, double *);

static void fill_nan(double *out, int count) {
    int i;
    for (i = 0; i < count; ++i) {
        out[i] = NAN;
    }
}

static void tau(const double *q, const double *qd, const double *qdd, double *out) {
    METHOD(inverse_dynamics)(q, qd, qdd, out);
}

static void mass(const double *q, const double *qd, const double *qdd, double *out) {
    (void)qd, (void)qdd;
    METHOD(mass_matrix)(q, (double (*)[DOF])out);
}

static void gravity(const double *q, const double *qd, const double *qdd, double *out) {
    (void)qd, (void)qdd;
    METHOD(gravity_torques)(q, out);
}

static void coriolis(const double *q, const double *qd, const double *qdd, double *out) {
    (void)qdd;
    METHOD(coriolis_matrix)(q, qd, (double (*)[DOF])out);
}

static void bias(const double *q, const double *qd, const double *qdd, double *out) {
    (void)qdd;
    METHOD(bias_torques)(q, qd, out);
}

static void hand_pose(const double *q, const double *qd, const double *qdd, double *out) {
    (void)qd, (void)qdd;
    METHOD(hand_pose)(q, (double (*)[4])out);
}

static void jacobian(const double *q, const double *qd, const double *qdd, double *out) {
    (void)qd, (void)qdd;
    METHOD(hand_jacobian_in_base)(q, (double (*)[DOF])out);
}

/* The wrench is the third input, as in bench/ffi. */
static void statics(const double *q, const double *qd, const double *wrench, double *out) {
    (void)qd;
    METHOD(joint_torques_for_base_wrench)(q, wrench, out);
}

static void forward(const double *q, const double *qd, const double *torques, double *out) {
    if (METHOD(forward_dynamics)(q, qd, torques, out) != 0) {
        fill_nan(out, DOF);
    }
}

static void mass_inverse(const double *q, const double *qd, const double *qdd, double *out) {
    (void)qd, (void)qdd;
    if (METHOD(mass_matrix_inverse)(q, (double (*)[DOF])out) != 0) {
        fill_nan(out, DOF * DOF);
    }
}

static void inverse_derivatives(const double *q, const double *qd, const double *qdd, double *out) {
    METHOD(inverse_dynamics_derivatives)(q, qd, qdd, (double (*)[DOF][DOF])out);
}

/* q̈ itself, which the header's function also gives, is not part of bench/ffi's output. */
static void forward_derivatives(const double *q, const double *qd, const double *torques, double *out) {
    double qdd[DOF];
    if (METHOD(forward_dynamics_derivatives)(q, qd, torques, qdd, (double (*)[DOF][DOF])out) != 0) {
        fill_nan(out, 3 * DOF * DOF);
    }
}

static void regressor(const double *q, const double *qd, const double *qdd, double *out) {
    METHOD(regressor)(q, qd, qdd, (double (*)[DOF][10])out);
}

static void base_regressor(const double *q, const double *qd, const double *qdd, double *out) {
    METHOD(base_regressor)(q, qd, qdd, (double (*)[BASE])out);
}

static void base_parameters(const double *q, const double *qd, const double *qdd, double *out) {
    (void)q, (void)qd, (void)qdd;
    METHOD(base_parameters)(out);
}

function JOIN(dynamics_bench_c, NAME)(const char *name);

function JOIN(dynamics_bench_c, NAME)(const char *name) {
    static const struct {
        const char *name;
        function f;
    } table[] = {
        {"tau", tau},
        {"M", mass},
        {"g", gravity},
        {"C", coriolis},
        {"h", bias},
        {"fk", hand_pose},
        {"J", jacobian},
        {"JtF", statics},
        {"fd", forward},
        {"Minv", mass_inverse},
        {"dtau", inverse_derivatives},
        {"dqdd", forward_derivatives},
        {"Y", regressor},
        {"YB", base_regressor},
        {"piB", base_parameters},
    };
    size_t i;
    for (i = 0; i < sizeof table / sizeof table[0]; ++i) {
        if (name != NULL && strcmp(name, table[i].name) == 0) {
            return table[i].f;
        }
    }
    return NULL;
}
