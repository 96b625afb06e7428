// Pinocchio side of the side-by-side benchmark (see bench/README.md; driven by bench/run).
//
// Usage: pinocchio_bench [--generated LIB.so [--c LIB.so [--casadi LIB.so]]] DATA.json [DATA.json ...]
//
// Each argument is a reference data file, of tests/data/reference/data/, tests/data/panda/,
// tests/data/urdf/ (format in tests/data/reference/README.md) or tests/data/trees/ (a robot that
// branches, its joints' "parents" given: no hand frame, so no fk, J, JtF, and no Y, YB; the
// other functions as below), or tests/data/floating/ (a robot on a free-flying base: tau, M, h
// and g alone, floating.hpp). For each other file the program
//   1. builds a Pinocchio model from the file's "description" exactly as the reference data were
//      built (one JointModelRZ / JointModelPZ per D-H joint, placements from the D-H pre/post
//      transforms, link inertias mapped with post_i.act(...), armature = actuator inertias,
//      gravity = the JSON gravity), or, for a URDF robot, from its "pinocchio_model": the model
//      Pinocchio's URDF loader built (tests/data/urdf/make.py), joint type by joint type,
//   2. checks rnea, crba, computeGeneralizedGravity, computeCoriolisMatrix and nonLinearEffects
//      against the file's sample CHECK_SAMPLE (relative tolerance 1e-9) and aborts on a mismatch,
//      so that the timed model is the right robot; likewise the hand frame's placement and its
//      Jacobian in LOCAL_WORLD_ALIGNED where the file has them ("ee_pose", "jacobian"). The hand
//      frame is an operational frame on the last joint: the D-H table's last post transform, or
//      for a URDF robot the placement that sample 0's "ee_pose" gives (checked on CHECK_SAMPLE),
//   3. times each function with the shared protocol: the 20 samples' (q, qd, qdd) used
//      cyclically, WARMUP calls, then BATCHES batches of CALLS calls, ns per call of a batch =
//      elapsed / CALLS (std::chrono::steady_clock), report the median over the batches. Beside
//      the dynamics: the hand pose (`fk`: forwardKinematics + updateFramePlacement), the hand's
//      Jacobian (`J`: computeFrameJacobian, LOCAL_WORLD_ALIGNED) and the statics (`JtF`: that
//      Jacobian, then Jᵀ F for a wrench F in base axes, the sample's first six qdd); the forward
//      dynamics (`fd`: aba at the sample's (q, qd, tau)) and M⁻¹ (`Minv`: computeMinverse, which
//      fills the upper triangle only, as crba does for `M`), where the file's M is positive
//      definite at every sample (not the reference UR5, whose M66 is 0): checked first, aba
//      against the sample's qdd and Minv (mirrored) by Minv M = I, on every sample. The
//      derivatives: `dtau` (computeRNEADerivatives at (q, qd, qdd), which also fills M) and,
//      where M is positive definite, `dqdd` (computeABADerivatives at (q, qd, tau), which also
//      gives qdd and Minv). The joint torque regressor `Y` (computeJointTorqueRegressor at
//      (q, qd, qdd), n × 10 n, each link's ten columns about Pinocchio's joint frame), and `YB`:
//      the same, then its base columns gathered (Pinocchio has no base regressor; the columns a
//      QR with column pivoting of Y stacked over the samples finds independent, found once).
//      The generated `M` (`mass_matrix_into`) writes into a matrix of its own, kept across the
//      calls and zeroed once, as crba keeps data.M: a tree's leaves its zero blocks unwritten.
//
// Output: one line per (robot, function) on stdout, `robot<TAB>function<TAB>median_ns`, robot =
// the file's "robot". A checksum (one output element per call, summed) goes to stderr so that the
// optimizer cannot drop the work.
//
// With --generated LIB.so (the cdylib of bench/ffi, the generated code of the same robots behind
// a C ABI), the program also loads the generated functions, checks each against the reference
// data on every sample (the same tolerance), and times the two sides in turn, batch by batch
// (Pinocchio then generated, then generated then Pinocchio, ...), so that both see the same load
// of this shared machine. The kinematics (fk, J, JtF) are checked against Pinocchio's on every
// sample, with JtF's wrench the first six values of qdd; fd and Minv as Pinocchio's are (fd's
// third input is the sample's tau); dtau and dqdd against Pinocchio's derivatives; Y against
// Pinocchio's regressor where the link frames are known (a D-H model: Y_pinocchio T, T the
// parameters of each link frame carried to its joint frame), not for a URDF model; YB times piB
// (the base parameters) against the data's tau. Each line
// then reads
// `robot<TAB>function<TAB>pinocchio_ns<TAB>generated_ns`, each the median over its own batches;
// a robot the library does not have (dynamics_bench_dof 0) keeps Pinocchio's column alone.
//
// With --c LIB.so as well (bench/c/robot.c: the headers of `dynamics emit --lang c` of the same
// robots, compiled as C99, one lookup dynamics_bench_c_<robot> per robot), the C functions are
// checked as the generated ones are, and timed in turn with the two others (the order rotating
// from batch to batch): `robot<TAB>function<TAB>pinocchio_ns<TAB>generated_ns<TAB>c_ns`. The
// batch rows, which the headers do not have, keep four columns.
//
// With --casadi LIB.so after --generated and --c (the generated-code peer: Pinocchio's rnea, crba,
// computeRNEADerivatives and computeABADerivatives traced on casadi::SX and exported as C by
// bench/casadi/generate.cpp, one lookup casadi_bench_<robot>(function) per robot, the functions'
// signatures and layouts bench/ffi's, each in three variants: "tau:plain", "tau:cse",
// "tau:snap"), those four are checked, every variant, against Pinocchio's doubles on every
// sample (the same tolerance); the fastest variant of each (short batches of each in turn,
// fastest_variant) is timed in turn with the others, a sixth column and its name a seventh:
// `robot<TAB>function<TAB>pinocchio_ns<TAB>generated_ns<TAB>c_ns<TAB>casadi_ns<TAB>variant`,
// c_ns `-` for a robot without C headers (the trees).
//
// For a robot whose generated library has simplified models (bench/ffi's `tau_simplified`,
// `M_simplified`, `g_simplified`: PUMA 560 and the Panda), those are checked against Pinocchio
// within their proven bounds at states drawn in their envelope (check_simplified), then timed
// in turn with Pinocchio's exact rnea, crba and computeGeneralizedGravity, four columns.

#include <algorithm>
#include <array>
#include <chrono>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <dlfcn.h>

#include <Eigen/QR>

#include "model.hpp"

#include "pinocchio/algorithm/aba.hpp"
#include "pinocchio/algorithm/aba-derivatives.hpp"
#include "pinocchio/algorithm/parallel/aba.hpp"
#include "pinocchio/algorithm/parallel/rnea.hpp"
#include "pinocchio/algorithm/crba.hpp"
#include "pinocchio/algorithm/frames.hpp"
#include "pinocchio/algorithm/kinematics.hpp"
#include "pinocchio/algorithm/regressor.hpp"
#include "pinocchio/algorithm/rnea.hpp"
#include "pinocchio/algorithm/rnea-derivatives.hpp"

// ---------------------------------------------------------------------------------------------
// Check against the reference data
// ---------------------------------------------------------------------------------------------

static const double TOLERANCE = 1e-9;
static const std::size_t CHECK_SAMPLE = 5;

// The tolerance of `robot`'s checks: TOLERANCE, but 1e-6 for the Allegro hand, whose thumb's
// first axis is 9e-10 rad off parallel to the palm's in the URDF; the generator takes such axes
// as parallel, a change of the robot that its small links' forward dynamics and derivatives (M
// is at most 1.1e-3 kg m²) show at 4e-8 (tests/tests/it/urdf_trees.rs checks the same change).
static double tolerance_of(const std::string & robot)
{
  return robot == "allegro_right_hand" ? 1e-6 : TOLERANCE;
}

// max|got - want| / max(1, max|want|) must not exceed the robot's tolerance.
static void check(
  const std::string & robot,
  const std::string & what,
  const Eigen::MatrixXd & got,
  const Eigen::MatrixXd & want,
  std::size_t sample = CHECK_SAMPLE)
{
  if (got.rows() != want.rows() || got.cols() != want.cols())
  {
    std::fprintf(stderr, "%s: %s has the wrong shape\n", robot.c_str(), what.c_str());
    std::exit(1);
  }
  const double err = (got - want).cwiseAbs().maxCoeff() / std::max(1.0, want.cwiseAbs().maxCoeff());
  const double tolerance = tolerance_of(robot);
  if (!(err <= tolerance))
  {
    std::fprintf(
      stderr, "%s: %s differs from the reference (sample %zu) by %.3e relative (> %.0e): wrong model?\n",
      robot.c_str(), what.c_str(), sample, err, tolerance);
    std::exit(1);
  }
}

// The 3 × 4 rows [R | p] of a placement.
static Eigen::MatrixXd rows_of(const SE3 & m)
{
  Eigen::MatrixXd out(3, 4);
  out << m.rotation(), m.translation();
  return out;
}

// The hand's placement, its Jacobian in base axes (LOCAL_WORLD_ALIGNED) and Jᵀ F.
struct Hand
{
  Eigen::MatrixXd pose, J;
  Eigen::VectorXd JtF;
};

static Hand hand_of(const Model & model, pinocchio::FrameIndex hand, const Eigen::VectorXd & q, const Eigen::VectorXd & F)
{
  Data data(model);
  Hand out;
  pinocchio::forwardKinematics(model, data, q);
  out.pose = rows_of(pinocchio::updateFramePlacement(model, data, hand));
  out.J = Eigen::MatrixXd::Zero(6, model.nv);
  pinocchio::computeFrameJacobian(model, data, q, hand, pinocchio::LOCAL_WORLD_ALIGNED, out.J);
  out.JtF = out.J.transpose() * F;
  return out;
}

static void check_model(
  const std::string & robot, const Model & model, pinocchio::FrameIndex hand, const json::Value & sample)
{
  Data data(model);
  const Eigen::VectorXd q = vecn(sample["q"]), v = vecn(sample["qd"]), a = vecn(sample["qdd"]);
  check(robot, "tau (rnea)", pinocchio::rnea(model, data, q, v, a), vecn(sample["tau"]));
  Eigen::MatrixXd M = pinocchio::crba(model, data, q); // upper triangle only
  M.triangularView<Eigen::StrictlyLower>() = M.transpose().triangularView<Eigen::StrictlyLower>();
  check(robot, "M (crba)", M, matn(sample["M"]));
  check(robot, "g (computeGeneralizedGravity)", pinocchio::computeGeneralizedGravity(model, data, q), vecn(sample["g"]));
  check(robot, "C (computeCoriolisMatrix)", pinocchio::computeCoriolisMatrix(model, data, q, v), matn(sample["C"]));
  check(robot, "h (nonLinearEffects)", pinocchio::nonLinearEffects(model, data, q, v), vecn(sample["h"]));
  if (sample.has("ee_pose") && sample.has("jacobian"))
  {
    const Hand got = hand_of(model, hand, q, a.head<6>());
    check(robot, "hand pose (updateFramePlacement)", got.pose, matn(sample["ee_pose"]).topRows(3));
    check(robot, "hand Jacobian (computeFrameJacobian)", got.J, matn(sample["jacobian"]));
  }
}

// Whether the file's M is positive definite at every sample: the forward dynamics and M⁻¹ are
// only timed there.
static bool invertible(const json::Value & samples)
{
  for (std::size_t s = 0; s < samples.size(); ++s)
    if (Eigen::LLT<Eigen::MatrixXd>(matn(samples[s]["M"])).info() != Eigen::Success)
      return false;
  return true;
}

// The n × n Minv, its lower triangle mirrored from the upper one that computeMinverse fills.
static Eigen::MatrixXd symmetric(Eigen::MatrixXd m)
{
  m.triangularView<Eigen::StrictlyLower>() = m.transpose().triangularView<Eigen::StrictlyLower>();
  return m;
}

// The skew matrix of v: S(v) w = v × w.
static Eigen::Matrix3d skew(const Eigen::Vector3d & v)
{
  Eigen::Matrix3d S;
  S << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return S;
}

// T, 10 × 10: a link's parameters π = [m, hx, hy, hz, Ixx, Ixy, Iyy, Ixz, Iyz, Izz]
// (toDynamicParameters' order: first moment h = m c, inertia about the frame's origin) about
// its link frame, carried to its joint frame, the link frame at jMl = (R, p): m' = m,
// h' = R h + m p, I' = R I Rᵀ − S(Rh) S(p) − S(p) S(Rh) − m S(p)². Linear, so column k is
// the image of the k-th unit vector; Pinocchio's regressor times T is the regressor of π.
static Eigen::Matrix<double, 10, 10> link_to_joint(const SE3 & jMl)
{
  const Eigen::Matrix3d R = jMl.rotation();
  const Eigen::Matrix3d Sp = skew(jMl.translation());
  Eigen::Matrix<double, 10, 10> T;
  for (int k = 0; k < 10; ++k)
  {
    Eigen::Matrix<double, 10, 1> e = Eigen::Matrix<double, 10, 1>::Unit(k);
    const double m = e[0];
    const Eigen::Vector3d h(e[1], e[2], e[3]);
    Eigen::Matrix3d I;
    I << e[4], e[5], e[7], e[5], e[6], e[8], e[7], e[8], e[9];
    const Eigen::Vector3d Rh = R * h;
    const Eigen::Vector3d h2 = Rh + m * jMl.translation();
    const Eigen::Matrix3d I2 = R * I * R.transpose() - skew(Rh) * Sp - Sp * skew(Rh) - m * Sp * Sp;
    T.col(k) << m, h2, I2(0, 0), I2(0, 1), I2(1, 1), I2(0, 2), I2(1, 2), I2(2, 2);
  }
  return T;
}

// Pinocchio's regressor in link frames: each link's ten columns times its T.
static Eigen::MatrixXd regressor_in_link_frames(const Eigen::MatrixXd & Y, const std::vector<SE3> & links)
{
  Eigen::MatrixXd out(Y.rows(), Y.cols());
  for (std::size_t j = 0; j < links.size(); ++j)
  {
    const auto c = static_cast<Eigen::Index>(10 * j);
    out.middleCols<10>(c) = Y.middleCols<10>(c) * link_to_joint(links[j]);
  }
  return out;
}

// Pinocchio's aba and computeMinverse on every sample: aba(q, qd, tau) = qdd and Minv M = I.
static void check_forward(const std::string & robot, const Model & model, const json::Value & samples)
{
  Data data(model);
  for (std::size_t s = 0; s < samples.size(); ++s)
  {
    const json::Value & sample = samples[s];
    const Eigen::VectorXd q = vecn(sample["q"]), v = vecn(sample["qd"]), tau = vecn(sample["tau"]);
    check(robot, "qdd (aba)", pinocchio::aba(model, data, q, v, tau), vecn(sample["qdd"]), s);
    const Eigen::MatrixXd M = matn(sample["M"]);
    const Eigen::MatrixXd Minv = symmetric(pinocchio::computeMinverse(model, data, q));
    check(robot, "Minv M (computeMinverse)", Minv * M, Eigen::MatrixXd::Identity(M.rows(), M.cols()), s);
  }
}

// ---------------------------------------------------------------------------------------------
// Timing protocol (the same as the Rust side's `timings`)
// ---------------------------------------------------------------------------------------------

static const int WARMUP = 10000;
static const int BATCHES = 31;
static const int CALLS = 20000;
// BENCH_CHECK_ONLY=1: every check, but one call a batch, so that the figures mean nothing (for
// checking a library built unoptimized, whose timing would take hours).
static bool CHECK_ONLY = false;

// The inputs are the samples' (q, qd, qdd), used cyclically. `f(k)` runs the function on sample
// k and returns one element of its output, which is added to `sum`; `k` moves on from call to
// call. Returns the batch's ns per call.
template<typename F>
static double batch_ns(F && f, int calls, std::size_t nsamples, std::size_t & k, double & sum)
{
  if (CHECK_ONLY)
    calls = 1;
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < calls; ++i)
  {
    sum += f(k);
    if (++k == nsamples)
      k = 0;
  }
  const auto t1 = std::chrono::steady_clock::now();
  return std::chrono::duration<double, std::nano>(t1 - t0).count() / static_cast<double>(calls);
}

static double median(std::vector<double> ns)
{
  std::sort(ns.begin(), ns.end());
  return ns[ns.size() / 2];
}

// WARMUP calls, then the median of BATCHES batches of CALLS calls.
template<typename F>
static double median_ns(std::size_t nsamples, F && f, double & checksum)
{
  std::size_t k = 0;
  double sum = 0.0;
  batch_ns(f, WARMUP, nsamples, k, sum);
  std::vector<double> ns(BATCHES);
  for (auto & t : ns)
    t = batch_ns(f, CALLS, nsamples, k, sum);
  checksum += sum;
  return median(ns);
}

// The same protocol for two functions timed in turn: warm-up calls of each, then BATCHES pairs
// of batches, the order within a pair alternating. Returns the two medians.
template<typename F, typename G>
static std::pair<double, double> median_ns_in_turn(
  std::size_t nsamples, F && f, G && g, double & checksum, int warmup = WARMUP, int calls = CALLS)
{
  std::size_t k = 0;
  double sum = 0.0;
  batch_ns(f, warmup, nsamples, k, sum);
  batch_ns(g, warmup, nsamples, k, sum);
  std::vector<double> ns_f(BATCHES), ns_g(BATCHES);
  for (std::size_t b = 0; b < ns_f.size(); ++b)
  {
    if (b % 2 == 0)
    {
      ns_f[b] = batch_ns(f, calls, nsamples, k, sum);
      ns_g[b] = batch_ns(g, calls, nsamples, k, sum);
    }
    else
    {
      ns_g[b] = batch_ns(g, calls, nsamples, k, sum);
      ns_f[b] = batch_ns(f, calls, nsamples, k, sum);
    }
  }
  checksum += sum;
  return {median(ns_f), median(ns_g)};
}

// The same for three or four functions: the order within a round of batches rotates (f g h,
// g h f, h f g), so that each is first, second, ... and last as often as the others. Returns
// the medians in the functions' order.
template<typename... Fs>
static std::array<double, sizeof...(Fs)> median_ns_rotating(std::size_t nsamples, double & checksum, Fs &&... fs)
{
  constexpr std::size_t m = sizeof...(Fs);
  std::size_t k = 0;
  double sum = 0.0;
  (batch_ns(fs, WARMUP, nsamples, k, sum), ...);
  std::array<std::vector<double>, m> ns;
  for (auto & v : ns)
    v.resize(BATCHES);
  for (std::size_t b = 0; b < static_cast<std::size_t>(BATCHES); ++b)
    for (std::size_t i = 0; i < m; ++i)
    {
      const std::size_t which = (b + i) % m;
      std::size_t index = 0;
      ((index++ == which ? static_cast<void>(ns[which][b] = batch_ns(fs, CALLS, nsamples, k, sum)) : static_cast<void>(0)), ...);
    }
  checksum += sum;
  std::array<double, m> medians;
  for (std::size_t i = 0; i < m; ++i)
    medians[i] = median(ns[i]);
  return medians;
}

// ---------------------------------------------------------------------------------------------
// The generated code (bench/ffi), loaded at run time
// ---------------------------------------------------------------------------------------------

// f(q, qd, qdd, out): out gets n × n values (M, C, row-major) or n (tau, g, h).
using GeneratedFunction = void (*)(const double *, const double *, const double *, double *);
using Lookup = GeneratedFunction (*)(const char *, const char *);

struct Generated
{
  Lookup lookup = nullptr;
  std::size_t (*dof)(const char *) = nullptr;
  std::size_t (*base_count)(const char *) = nullptr;
  std::size_t (*horizon)() = nullptr;
  // The simplified models' proven bounds and envelope (null in a library without them).
  std::size_t (*simplified_bounds)(const char *, const char *, double *) = nullptr;
  std::size_t (*simplified_envelope)(const char *, double *) = nullptr;

  explicit Generated(const std::string & path)
  {
    void * lib = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!lib)
      throw std::runtime_error(std::string("cannot load ") + path + ": " + dlerror());
    lookup = reinterpret_cast<Lookup>(dlsym(lib, "dynamics_bench_function"));
    dof = reinterpret_cast<std::size_t (*)(const char *)>(dlsym(lib, "dynamics_bench_dof"));
    base_count = reinterpret_cast<std::size_t (*)(const char *)>(dlsym(lib, "dynamics_bench_base_count"));
    horizon = reinterpret_cast<std::size_t (*)()>(dlsym(lib, "dynamics_bench_horizon"));
    simplified_bounds = reinterpret_cast<std::size_t (*)(const char *, const char *, double *)>(
      dlsym(lib, "dynamics_bench_simplified_bounds"));
    simplified_envelope = reinterpret_cast<std::size_t (*)(const char *, double *)>(
      dlsym(lib, "dynamics_bench_simplified_envelope"));
    if (!lookup || !dof || !base_count || !horizon)
      throw std::runtime_error(path + " does not export dynamics_bench_function, dynamics_bench_dof, dynamics_bench_base_count and dynamics_bench_horizon");
  }

  GeneratedFunction get(const std::string & robot, const char * function) const
  {
    GeneratedFunction f = lookup(robot.c_str(), function);
    if (!f)
      throw std::runtime_error("the generated code has no " + std::string(function) + " for " + robot);
    return f;
  }
};

// The C side (bench/c/robot.c, the headers of `dynamics emit --lang c`), loaded at run time: per
// robot one lookup, dynamics_bench_c_<robot>(function), of the functions bench/ffi has, with
// their signatures and layouts (not the batches). The CasADi peer's library alike
// (bench/casadi/generate.cpp: casadi_bench_<robot>(function), tau, M, dtau and dqdd alone).
struct CHeaders
{
  using RobotLookup = GeneratedFunction (*)(const char *);
  void * lib = nullptr;
  std::string prefix;

  CHeaders(const std::string & path, std::string lookup_prefix) : prefix(std::move(lookup_prefix))
  {
    lib = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!lib)
      throw std::runtime_error(std::string("cannot load ") + path + ": " + dlerror());
  }

  // The robot's lookup, or null where the library does not have the robot.
  RobotLookup robot(const std::string & name) const
  {
    return reinterpret_cast<RobotLookup>(dlsym(lib, (prefix + name).c_str()));
  }
};

// Looks a function up by name; throws where there is none (`Generated::get`'s contract).
using Getter = std::function<GeneratedFunction(const char *)>;

// The functions of one side with n joints and b base parameters (`label`: " (generated)",
// " (C)") against the reference data, on every sample; the kinematics against Pinocchio's; fd
// and Minv (`forward`) as check_forward checks Pinocchio's.
static void check_generated(
  const std::string & robot,
  const Getter & get,
  std::size_t n,
  std::size_t b,
  const std::string & at,
  const json::Value & samples,
  const Model & model,
  pinocchio::FrameIndex hand,
  bool forward,
  const std::vector<SE3> & links,
  bool tree)
{
  Data data(model);
  std::vector<double> out(std::max(10 * n * n, std::size_t(12)));
  // `M`'s own matrix, zeroed once and kept across the samples (a tree's `M` leaves the blocks
  // between its branches as it finds them), as it is kept when timed.
  std::vector<double> kept_M(n * n, 0.0);
  auto rows = [&](std::size_t r, std::size_t c) {
    Eigen::MatrixXd m(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c));
    for (std::size_t i = 0; i < r; ++i)
      for (std::size_t j = 0; j < c; ++j)
        m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = out[i * c + j];
    return m;
  };
  auto vector = [&](std::size_t len) {
    Eigen::MatrixXd v(static_cast<Eigen::Index>(len), 1);
    for (std::size_t i = 0; i < len; ++i)
      v(static_cast<Eigen::Index>(i), 0) = out[i];
    return v;
  };
  // The k-th n × n matrix of the output (the derivatives write two or three in a row).
  auto block = [&](std::size_t k) {
    Eigen::MatrixXd m(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    for (std::size_t r = 0; r < n; ++r)
      for (std::size_t c = 0; c < n; ++c)
        m(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = out[k * n * n + r * n + c];
    return m;
  };
  auto matrix = [&]() { return block(0); };
  for (std::size_t s = 0; s < samples.size(); ++s)
  {
    const json::Value & sample = samples[s];
    const Eigen::VectorXd q = vecn(sample["q"]), v = vecn(sample["qd"]), a = vecn(sample["qdd"]);
    if (static_cast<std::size_t>(q.size()) != n)
      throw std::runtime_error(robot + ": the generated code has " + std::to_string(n) + " joints");
    get("tau")(q.data(), v.data(), a.data(), out.data());
    check(robot, "tau" + at, vector(n), vecn(sample["tau"]), s);
    get("M")(q.data(), v.data(), a.data(), kept_M.data());
    std::copy(kept_M.begin(), kept_M.end(), out.begin());
    check(robot, "M" + at, matrix(), matn(sample["M"]), s);
    check(robot, "M" + at + " against Pinocchio", matrix(), symmetric(pinocchio::crba(model, data, q)), s);
    get("g")(q.data(), v.data(), a.data(), out.data());
    check(robot, "g" + at, vector(n), vecn(sample["g"]), s);
    get("C")(q.data(), v.data(), a.data(), out.data());
    check(robot, "C" + at, matrix(), matn(sample["C"]), s);
    get("h")(q.data(), v.data(), a.data(), out.data());
    check(robot, "h" + at, vector(n), vecn(sample["h"]), s);
    // A tree (tests/data/trees/) has no hand frame, regressor or base parameters here: its
    // dynamics and their derivatives alone.
    if (!tree)
    {
      const Hand want = hand_of(model, hand, q, a.head<6>());
      get("fk")(q.data(), v.data(), a.data(), out.data());
      check(robot, "fk" + at + " against Pinocchio", rows(3, 4), want.pose, s);
      get("J")(q.data(), v.data(), a.data(), out.data());
      check(robot, "J" + at + " against Pinocchio", rows(6, n), want.J, s);
      get("JtF")(q.data(), v.data(), a.data(), out.data());
      check(robot, "JtF" + at + " against Pinocchio", vector(n), want.JtF, s);
    }
    pinocchio::computeRNEADerivatives(model, data, q, v, a);
    get("dtau")(q.data(), v.data(), a.data(), out.data());
    check(robot, "dtau/dq" + at + " against Pinocchio", block(0), data.dtau_dq, s);
    check(robot, "dtau/dqd" + at + " against Pinocchio", block(1), data.dtau_dv, s);
    if (!tree)
    {
      get("Y")(q.data(), v.data(), a.data(), out.data());
      if (!links.empty())
      {
        const Eigen::MatrixXd Y = pinocchio::computeJointTorqueRegressor(model, data, q, v, a);
        check(robot, "Y" + at + " against Pinocchio", rows(n, 10 * n), regressor_in_link_frames(Y, links), s);
      }
      // The base regressor times the base parameters: the torques (the reference robots have no
      // springs), the rotors' inertia included.
      get("piB")(q.data(), v.data(), a.data(), out.data());
      const Eigen::MatrixXd base_parameters = vector(b);
      get("YB")(q.data(), v.data(), a.data(), out.data());
      check(robot, "YB piB" + at, rows(n, b) * base_parameters, vecn(sample["tau"]), s);
    }
    if (!forward)
      continue;
    const Eigen::VectorXd tau = vecn(sample["tau"]);
    pinocchio::computeABADerivatives(model, data, q, v, tau);
    get("dqdd")(q.data(), v.data(), tau.data(), out.data());
    check(robot, "dqdd/dq" + at + " against Pinocchio", block(0), data.ddq_dq, s);
    check(robot, "dqdd/dqd" + at + " against Pinocchio", block(1), data.ddq_dv, s);
    check(robot, "dqdd/dtau" + at + " against Pinocchio", block(2), symmetric(data.Minv), s);
    get("fd")(q.data(), v.data(), tau.data(), out.data());
    check(robot, "fd" + at, vector(n), a, s);
    get("Minv")(q.data(), v.data(), a.data(), out.data());
    const Eigen::MatrixXd M = matn(sample["M"]);
    check(robot, "Minv M" + at, matrix() * M, Eigen::MatrixXd::Identity(M.rows(), M.cols()), s);
  }
}

// The variants of each CasADi peer function (bench/casadi/generate.cpp), looked up as
// "FUNCTION:VARIANT": CasADi's defaults, common subexpressions eliminated, and the latter on a
// model whose constants near 0 and ±1 are exact.
static const char * const CASADI_VARIANTS[] = {"plain", "cse", "snap"};

// The CasADi peer's functions (`get`: null where it has none) against Pinocchio's doubles on
// every sample, every variant of each: tau (rnea), M (crba, mirrored), dtau
// (computeRNEADerivatives) and, with `forward`, dqdd (computeABADerivatives, M⁻¹ mirrored), at
// the robot's tolerance. Returns the names of the functions it has (some variant of), which
// are then timed.
static std::vector<std::string> check_casadi(
  const std::string & robot,
  const std::function<GeneratedFunction(const char *)> & get,
  const json::Value & samples,
  const Model & model,
  bool forward)
{
  Data data(model);
  const Eigen::Index n = model.nv;
  std::vector<double> out(static_cast<std::size_t>(3 * n * n));
  // The k-th n × n block of the output, row-major.
  auto block = [&](Eigen::Index k) {
    Eigen::MatrixXd m(n, n);
    for (Eigen::Index r = 0; r < n; ++r)
      for (Eigen::Index c = 0; c < n; ++c)
        m(r, c) = out[static_cast<std::size_t>(k * n * n + r * n + c)];
    return m;
  };
  // Each function and variant the library has.
  std::vector<std::string> have;
  std::vector<std::pair<std::string, std::string>> variants;
  for (const char * function : {"tau", "M", "dtau", "dqdd"})
  {
    if (!forward && std::string(function) == "dqdd")
      continue;
    for (const char * variant : CASADI_VARIANTS)
      if (get((std::string(function) + ":" + variant).c_str()))
        variants.emplace_back(function, variant);
    if (!variants.empty() && variants.back().first == function)
      have.push_back(function);
  }
  for (std::size_t s = 0; s < samples.size(); ++s)
  {
    const json::Value & sample = samples[s];
    const Eigen::VectorXd q = vecn(sample["q"]), v = vecn(sample["qd"]), a = vecn(sample["qdd"]);
    const Eigen::VectorXd tau = vecn(sample["tau"]);
    for (const auto & [function, variant] : variants)
    {
      const bool dqdd = function == "dqdd";
      get((function + ":" + variant).c_str())(q.data(), v.data(), dqdd ? tau.data() : a.data(), out.data());
      const std::string peer = " (CasADi, " + variant + ") against Pinocchio";
      if (function == "tau")
        check(robot, function + peer, Eigen::Map<const Eigen::VectorXd>(out.data(), n), pinocchio::rnea(model, data, q, v, a), s);
      else if (function == "M")
        check(robot, function + peer, block(0), symmetric(pinocchio::crba(model, data, q)), s);
      else if (function == "dtau")
      {
        pinocchio::computeRNEADerivatives(model, data, q, v, a);
        check(robot, "dtau/dq" + peer, block(0), data.dtau_dq, s);
        check(robot, "dtau/dqd" + peer, block(1), data.dtau_dv, s);
      }
      else
      {
        pinocchio::computeABADerivatives(model, data, q, v, tau);
        check(robot, "dqdd/dq" + peer, block(0), data.ddq_dq, s);
        check(robot, "dqdd/dqd" + peer, block(1), data.ddq_dv, s);
        check(robot, "dqdd/dtau" + peer, block(2), symmetric(data.Minv), s);
      }
    }
  }
  return have;
}

// The fastest of a CasADi function's variants (`get`: null where one is missing), by short
// batches of each in turn, each variant's fastest batch (the one least slowed by the
// machine's neighbours): PICK_ROUNDS rounds of PICK_CALLS calls of each. Returns its name, or
// an empty name where it has none.
static const int PICK_ROUNDS = 9;
static const int PICK_CALLS = 2000;
template<typename Call>
static std::string fastest_variant(
  const std::string & function,
  const std::function<GeneratedFunction(const char *)> & get,
  std::size_t nsamples,
  Call && call,
  double & checksum)
{
  std::vector<std::pair<std::string, GeneratedFunction>> variants;
  for (const char * variant : CASADI_VARIANTS)
    if (const GeneratedFunction f = get((function + ":" + variant).c_str()))
      variants.emplace_back(variant, f);
  std::vector<double> least(variants.size(), std::numeric_limits<double>::infinity());
  std::size_t k = 0;
  double sum = 0.0;
  for (int round = 0; round < PICK_ROUNDS; ++round)
    for (std::size_t i = 0; i < variants.size(); ++i)
    {
      const GeneratedFunction f = variants[i].second;
      auto one = [&](std::size_t sample) { return call(f, sample); };
      least[i] = std::min(least[i], batch_ns(one, PICK_CALLS, nsamples, k, sum));
    }
  checksum += sum;
  if (variants.empty())
    return "";
  return variants[static_cast<std::size_t>(std::min_element(least.begin(), least.end()) - least.begin())].first;
}

// The batch rows, per state: a horizon of `gen.horizon()` states (the samples in turn) in one
// call of the generated `_batch` functions, beside Pinocchio's own batch (rneaInParallel and
// abaInParallel on one thread of a ModelPool) or, where it has none (crba,
// computeRNEADerivatives, computeABADerivatives), a loop. The generated results are checked first against the
// generated single-state functions, state by state.
static void time_batches(
  const std::string & robot,
  const Generated & gen,
  const Model & model,
  const std::vector<Eigen::VectorXd> & qs,
  const std::vector<Eigen::VectorXd> & vs,
  const std::vector<Eigen::VectorXd> & as,
  const std::vector<Eigen::VectorXd> & taus,
  bool forward,
  double & checksum)
{
  const Eigen::Index n = model.nv, h = static_cast<Eigen::Index>(gen.horizon());
  Eigen::MatrixXd Q(n, h), V(n, h), A(n, h), TAU(n, h), OUT(n, h);
  for (Eigen::Index k = 0; k < h; ++k)
  {
    const std::size_t s = static_cast<std::size_t>(k) % qs.size();
    Q.col(k) = qs[s], V.col(k) = vs[s], A.col(k) = as[s], TAU.col(k) = taus[s];
  }
  std::vector<double> out(static_cast<std::size_t>(3 * n * n * h)), one(static_cast<std::size_t>(3 * n * n));
  // Each state's output of `batch` against the single-state `single`'s, `size` values each.
  auto check_batch = [&](const char * batch, const char * single, const Eigen::MatrixXd & third, Eigen::Index size) {
    gen.get(robot, batch)(Q.data(), V.data(), third.data(), out.data());
    for (Eigen::Index k = 0; k < h; ++k)
    {
      gen.get(robot, single)(Q.col(k).data(), V.col(k).data(), third.col(k).data(), one.data());
      const Eigen::Map<const Eigen::VectorXd> got(out.data() + k * size, size), want(one.data(), size);
      check(robot, std::string(batch) + " state " + std::to_string(k), got, want, static_cast<std::size_t>(k));
    }
  };
  check_batch("tau_batch", "tau", A, n);
  check_batch("M_batch", "M", A, n * n);
  check_batch("dtau_batch", "dtau", A, 2 * n * n);
  if (forward)
  {
    check_batch("fd_batch", "fd", TAU, n);
    check_batch("dqdd_batch", "dqdd", TAU, 3 * n * n);
  }
  pinocchio::ModelPool pool(model, 1);
  Data data(model);
  const int warmup = 100, calls = 200;
  auto row = [&](const char * function, const Eigen::MatrixXd & third, auto && pin) {
    const GeneratedFunction f = gen.get(robot, function);
    auto g = [&](std::size_t) {
      f(Q.data(), V.data(), third.data(), out.data());
      return out[0];
    };
    auto p = [&](std::size_t) { return pin(); };
    const auto [pin_ns, gen_ns] = median_ns_in_turn(1, p, g, checksum, warmup, calls);
    std::printf("%s\t%s\t%.1f\t%.1f\n", robot.c_str(), function, pin_ns / double(h), gen_ns / double(h));
    std::fflush(stdout);
  };
  row("tau_batch", A, [&] {
    pinocchio::rneaInParallel(1, pool, Q, V, A, OUT);
    return OUT(0, 0);
  });
  row("M_batch", A, [&] {
    double sum = 0.0;
    for (Eigen::Index k = 0; k < h; ++k)
      sum += pinocchio::crba(model, data, Q.col(k))(0, 0);
    return sum;
  });
  row("dtau_batch", A, [&] {
    double sum = 0.0;
    for (Eigen::Index k = 0; k < h; ++k)
    {
      pinocchio::computeRNEADerivatives(model, data, Q.col(k), V.col(k), A.col(k));
      sum += data.dtau_dq(0, 0);
    }
    return sum;
  });
  if (!forward)
    return;
  row("fd_batch", TAU, [&] {
    pinocchio::abaInParallel(1, pool, Q, V, TAU, OUT);
    return OUT(0, 0);
  });
  row("dqdd_batch", TAU, [&] {
    double sum = 0.0;
    for (Eigen::Index k = 0; k < h; ++k)
    {
      pinocchio::computeABADerivatives(model, data, Q.col(k), V.col(k), TAU.col(k));
      sum += data.ddq_dq(0, 0);
    }
    return sum;
  });
}

// The simplified models (bench/ffi's `tau_simplified`, `M_simplified`, `g_simplified`, for the
// robots whose derives ask for them) against Pinocchio's rnea, crba and
// computeGeneralizedGravity at CHECK_STATES states drawn in their envelope: each element within
// its proven bound (dynamics_bench_simplified_bounds: the generator's interval bound over the
// envelope) plus TOLERANCE relative, for the two sides' rounding; an element of an output left
// exact (bound 0) within TOLERANCE alone. Not the reference samples: their q spans ±π, mostly
// outside the envelopes. The worst sampled error over the bound goes to stderr. Returns
// whether the robot has simplified models; exits on a mismatch.
static const int CHECK_STATES = 2000;

static bool check_simplified(const std::string & robot, const Generated & gen, const Model & model)
{
  const auto n = static_cast<std::size_t>(model.nv);
  std::vector<double> envelope(4 * n);
  if (!gen.simplified_envelope || gen.simplified_envelope(robot.c_str(), envelope.data()) != n)
    return false;
  struct Output
  {
    const char * name;
    std::vector<double> bound;
    double worst;
  };
  std::vector<Output> outputs = {{"tau_simplified", {}, 0.0}, {"M_simplified", {}, 0.0}, {"g_simplified", {}, 0.0}};
  for (auto & o : outputs)
  {
    o.bound.resize(n * n);
    o.bound.resize(gen.simplified_bounds(robot.c_str(), o.name, o.bound.data()));
    if (o.bound.empty())
      throw std::runtime_error(robot + ": the generated code has no bounds of " + o.name);
  }
  std::mt19937_64 rng(17);
  auto uniform = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
  Data data(model);
  std::vector<double> out(n * n);
  Eigen::VectorXd q(model.nv), v(model.nv), a(model.nv);
  for (int s = 0; s < CHECK_STATES; ++s)
  {
    for (Eigen::Index i = 0; i < model.nv; ++i)
    {
      const double * e = &envelope[4 * static_cast<std::size_t>(i)];
      q[i] = uniform(e[0], e[1]), v[i] = uniform(-e[2], e[2]), a[i] = uniform(-e[3], e[3]);
    }
    Eigen::MatrixXd M = pinocchio::crba(model, data, q); // upper triangle only
    M.triangularView<Eigen::StrictlyLower>() = M.transpose().triangularView<Eigen::StrictlyLower>();
    // M is symmetric: its column-major values are the row-major ones the generated code writes.
    const Eigen::MatrixXd want[3] = {
      pinocchio::rnea(model, data, q, v, a), M, pinocchio::computeGeneralizedGravity(model, data, q)};
    for (std::size_t k = 0; k < outputs.size(); ++k)
    {
      Output & o = outputs[k];
      gen.get(robot, o.name)(q.data(), v.data(), a.data(), out.data());
      const double scale = std::max(1.0, want[k].cwiseAbs().maxCoeff());
      for (std::size_t i = 0; i < o.bound.size(); ++i)
      {
        const double err = std::abs(out[i] - want[k].data()[i]);
        if (!(err <= o.bound[i] + TOLERANCE * scale))
        {
          std::fprintf(
            stderr, "%s: %s[%zu] differs from Pinocchio by %.3e at a state of its envelope, over its proven bound %.3e\n",
            robot.c_str(), o.name, i, err, o.bound[i]);
          std::exit(1);
        }
        if (o.bound[i] > 0.0)
          o.worst = std::max(o.worst, err / o.bound[i]);
      }
    }
  }
  for (const auto & o : outputs)
    if (*std::max_element(o.bound.begin(), o.bound.end()) > 0.0)
      std::fprintf(
        stderr, "%s: %s within its proven bounds of Pinocchio at %d states of the envelope; worst error over the bound %.3f\n",
        robot.c_str(), o.name, CHECK_STATES, o.worst);
    else
      std::fprintf(
        stderr, "%s: %s left exact (bound 0): within %.0e of Pinocchio at %d states of the envelope\n",
        robot.c_str(), o.name, TOLERANCE, CHECK_STATES);
  return true;
}

// The columns of Pinocchio's regressor that a QR with column pivoting of it, stacked over the
// samples, finds independent: the numerical way to a base regressor.
static std::vector<Eigen::Index> base_columns(
  const Model & model,
  const std::vector<Eigen::VectorXd> & qs,
  const std::vector<Eigen::VectorXd> & vs,
  const std::vector<Eigen::VectorXd> & as)
{
  Data data(model);
  const Eigen::Index n = model.nv;
  Eigen::MatrixXd stacked(n * static_cast<Eigen::Index>(qs.size()), 10 * n);
  for (std::size_t k = 0; k < qs.size(); ++k)
    stacked.middleRows(n * static_cast<Eigen::Index>(k), n) =
      pinocchio::computeJointTorqueRegressor(model, data, qs[k], vs[k], as[k]);
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(stacked);
  qr.setThreshold(1e-9);
  std::vector<Eigen::Index> columns;
  for (Eigen::Index c = 0; c < qr.rank(); ++c)
    columns.push_back(qr.colsPermutation().indices()[c]);
  return columns;
}

// The robots on a free-flying base: run_floating.
#include "floating.hpp"

int main(int argc, char ** argv)
{
  int first = 1;
  const char * check_only = std::getenv("BENCH_CHECK_ONLY");
  CHECK_ONLY = check_only && std::string(check_only) == "1";
  if (CHECK_ONLY)
    std::fprintf(stderr, "BENCH_CHECK_ONLY=1: every check, one call a batch: the figures are not timings\n");
  std::unique_ptr<Generated> generated;
  std::unique_ptr<CHeaders> c_headers;
  std::unique_ptr<CHeaders> casadi_peer;
  try
  {
    if (argc > first + 1 && std::string(argv[first]) == "--generated")
    {
      generated = std::make_unique<Generated>(argv[first + 1]);
      first += 2;
    }
    if (argc > first + 1 && std::string(argv[first]) == "--c")
    {
      if (!generated)
        throw std::runtime_error("--c comes with --generated, after it");
      c_headers = std::make_unique<CHeaders>(argv[first + 1], "dynamics_bench_c_");
      first += 2;
    }
    if (argc > first + 1 && std::string(argv[first]) == "--casadi")
    {
      if (!generated)
        throw std::runtime_error("--casadi comes with --generated, after it (and after --c)");
      casadi_peer = std::make_unique<CHeaders>(argv[first + 1], "casadi_bench_");
      first += 2;
    }
  }
  catch (const std::exception & e)
  {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  if (argc <= first)
  {
    std::fprintf(stderr, "usage: %s [--generated LIB.so [--c LIB.so [--casadi LIB.so]]] DATA.json [DATA.json ...]\n", argv[0]);
    return 2;
  }
  double checksum = 0.0;
  for (int arg = first; arg < argc; ++arg)
  {
    const std::string path = argv[arg];
    std::string robot;
    json::Value file;
    Model model;
    pinocchio::FrameIndex hand;
    // Each link frame's placement on its joint: a D-H model's, from its table; a URDF model's
    // link frames are its joint frames, as the generator's regressor has them.
    std::vector<SE3> links;
    // A robot that branches (tests/data/trees/: its joints' "parents"): no hand frame, so no fk,
    // J, JtF; no regressor rows.
    bool tree = false;
    try
    {
      file = json::parse_file(path);
      robot = file["robot"].string();
      // A robot on a free-flying base (tests/data/floating/): its own checks and rows.
      if (file.has("floating_body"))
      {
        run_floating(robot, file, path, generated.get(), checksum);
        continue;
      }
      tree = file.has("parents");
      SE3 placement = SE3::Identity();
      if (tree)
      {
        model = build_model_from_pinocchio(file["pinocchio_model"]);
        links.assign(static_cast<std::size_t>(model.njoints - 1), SE3::Identity());
      }
      else if (file.has("pinocchio_model"))
      {
        // The tip link's placement on the last joint, from sample 0's pose (oMi⁻¹ · oMtip).
        model = build_model_from_pinocchio(file["pinocchio_model"]);
        links.assign(static_cast<std::size_t>(model.njoints - 1), SE3::Identity());
        Data data(model);
        pinocchio::forwardKinematics(model, data, vecn(file["samples"][0]["q"]));
        const Eigen::MatrixXd tip = matn(file["samples"][0]["ee_pose"]);
        placement = data.oMi[static_cast<std::size_t>(model.njoints - 1)].inverse()
                    * SE3(Eigen::Matrix3d(tip.topLeftCorner(3, 3)), Eigen::Vector3d(tip.topRightCorner(3, 1)));
      }
      else
        model = build_model(file["description"], placement, links);
      hand = add_hand_frame(model, placement);
    }
    catch (const std::exception & e)
    {
      std::fprintf(stderr, "%s: %s\n", path.c_str(), e.what());
      return 1;
    }
    const json::Value & samples = file["samples"];
    check_model(robot, model, hand, samples[CHECK_SAMPLE]);
    const bool forward = invertible(samples);
    if (forward)
      check_forward(robot, model, samples);
    else
      std::fprintf(stderr, "%s: M is not positive definite at every sample: no fd, no Minv\n", robot.c_str());
    // A robot the library does not have (dof 0) gets Pinocchio's column alone.
    const bool with_generated = generated && generated->dof(robot.c_str()) != 0;
    if (generated && !with_generated)
      std::fprintf(stderr, "%s: not in the generated library: Pinocchio alone\n", robot.c_str());
    // The C side of the robot, where the C library has it: its functions are bench/ffi's,
    // with the same number of joints and base parameters (the same description).
    const CHeaders::RobotLookup c_robot = with_generated && c_headers ? c_headers->robot(robot) : nullptr;
    if (c_headers && with_generated && !c_robot)
      std::fprintf(stderr, "%s: not in the C library: no C column\n", robot.c_str());
    auto c_get = [&](const char * function) {
      const GeneratedFunction f = c_robot(function);
      if (!f)
        throw std::runtime_error("the C headers have no " + std::string(function) + " for " + robot);
      return f;
    };
    // The CasADi peer of the robot, where its library has it (its column follows the C's), and
    // the functions of it that are checked, then timed.
    const CHeaders::RobotLookup casadi_robot = with_generated && casadi_peer ? casadi_peer->robot(robot) : nullptr;
    if (casadi_peer && with_generated && !casadi_robot)
      std::fprintf(stderr, "%s: not in the CasADi library: no CasADi column\n", robot.c_str());
    std::vector<std::string> casadi_functions;
    bool with_simplified = false;
    if (with_generated)
    {
      try
      {
        const std::size_t n = generated->dof(robot.c_str()), b = generated->base_count(robot.c_str());
        auto rust_get = [&](const char * function) { return generated->get(robot, function); };
        check_generated(robot, rust_get, n, b, " (generated)", samples, model, hand, forward, links, tree);
        with_simplified = check_simplified(robot, *generated, model);
        if (c_robot)
          check_generated(robot, c_get, n, b, " (C)", samples, model, hand, forward, links, tree);
        if (casadi_robot)
          casadi_functions = check_casadi(robot, casadi_robot, samples, model, forward);
      }
      catch (const std::exception & e)
      {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
      }
    }

    std::vector<Eigen::VectorXd> qs, vs, as, taus;
    for (std::size_t s = 0; s < samples.size(); ++s)
    {
      qs.push_back(vecn(samples[s]["q"]));
      vs.push_back(vecn(samples[s]["qd"]));
      as.push_back(vecn(samples[s]["qdd"]));
      taus.push_back(vecn(samples[s]["tau"]));
    }
    const std::size_t ns = qs.size();
    Data data(model);

    const auto n = static_cast<std::size_t>(qs[0].size());
    std::vector<double> out(std::max(10 * n * n, std::size_t(12)));
    // `M`'s matrix, kept across its calls and zeroed once, as Pinocchio keeps `data.M`: a tree's
    // generated `M` (`mass_matrix_into`) writes the elements along its branches alone.
    std::vector<double> kept_M(n * n, 0.0);
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(6, model.nv);
    Eigen::VectorXd JtF(model.nv);
    // Pinocchio's `function`, and the generated one in turn with it when it is loaded, the
    // generated one given `third` as its third input and `into` as its output.
    auto time_into = [&](const char * function, const std::vector<Eigen::VectorXd> & third, double * into, auto && pin) {
      if (!with_generated)
      {
        std::printf("%s\t%s\t%.1f\n", robot.c_str(), function, median_ns(ns, pin, checksum));
      }
      else
      {
        const GeneratedFunction f = generated->get(robot, function);
        auto gen = [&](std::size_t k) {
          f(qs[k].data(), vs[k].data(), third[k].data(), into);
          return into[0];
        };
        const bool peer =
          std::find(casadi_functions.begin(), casadi_functions.end(), function) != casadi_functions.end();
        // The CasADi peer, through the same kind of call: its fastest variant, timed as the
        // others are, and named in a last column.
        auto call = [&](GeneratedFunction f, std::size_t k) {
          f(qs[k].data(), vs[k].data(), third[k].data(), into);
          return into[0];
        };
        const std::string variant = peer ? fastest_variant(function, casadi_robot, ns, call, checksum) : "";
        const GeneratedFunction fp = peer ? casadi_robot((function + (":" + variant)).c_str()) : nullptr;
        auto casadi = [&](std::size_t k) { return call(fp, k); };
        if (!c_robot && !peer)
        {
          const auto [pin_ns, gen_ns] = median_ns_in_turn(ns, pin, gen, checksum);
          std::printf("%s\t%s\t%.1f\t%.1f\n", robot.c_str(), function, pin_ns, gen_ns);
        }
        else if (!c_robot)
        {
          // A robot without C headers (a tree): `-` in the C's column.
          const auto [pin_ns, gen_ns, casadi_ns] = median_ns_rotating(ns, checksum, pin, gen, casadi);
          std::printf(
            "%s\t%s\t%.1f\t%.1f\t-\t%.1f\t%s\n", robot.c_str(), function, pin_ns, gen_ns, casadi_ns, variant.c_str());
        }
        else
        {
          // The C in turn with both, through the same kind of call as the Rust.
          const GeneratedFunction fc = c_get(function);
          auto c = [&](std::size_t k) {
            fc(qs[k].data(), vs[k].data(), third[k].data(), into);
            return into[0];
          };
          if (!peer)
          {
            const auto [pin_ns, gen_ns, c_ns] = median_ns_rotating(ns, checksum, pin, gen, c);
            std::printf("%s\t%s\t%.1f\t%.1f\t%.1f\n", robot.c_str(), function, pin_ns, gen_ns, c_ns);
          }
          else
          {
            const auto [pin_ns, gen_ns, c_ns, casadi_ns] = median_ns_rotating(ns, checksum, pin, gen, c, casadi);
            std::printf(
              "%s\t%s\t%.1f\t%.1f\t%.1f\t%.1f\t%s\n",
              robot.c_str(),
              function,
              pin_ns,
              gen_ns,
              c_ns,
              casadi_ns,
              variant.c_str());
          }
        }
      }
      std::fflush(stdout);
    };
    auto time_with = [&](const char * function, const std::vector<Eigen::VectorXd> & third, auto && pin) {
      time_into(function, third, out.data(), pin);
    };
    auto time = [&](const char * function, auto && pin) { time_with(function, as, pin); };
    time("tau", [&](std::size_t k) {
      return pinocchio::rnea(model, data, qs[k], vs[k], as[k])[0];
    });
    time_into("M", as, kept_M.data(), [&](std::size_t k) {
      return pinocchio::crba(model, data, qs[k])(0, 0);
    });
    time("g", [&](std::size_t k) {
      return pinocchio::computeGeneralizedGravity(model, data, qs[k])[0];
    });
    time("C", [&](std::size_t k) {
      return pinocchio::computeCoriolisMatrix(model, data, qs[k], vs[k])(0, 0);
    });
    time("h", [&](std::size_t k) {
      return pinocchio::nonLinearEffects(model, data, qs[k], vs[k])[0];
    });
    if (!tree)
    {
      time("fk", [&](std::size_t k) {
        pinocchio::forwardKinematics(model, data, qs[k]);
        return pinocchio::updateFramePlacement(model, data, hand).translation()[0];
      });
      time("J", [&](std::size_t k) {
        pinocchio::computeFrameJacobian(model, data, qs[k], hand, pinocchio::LOCAL_WORLD_ALIGNED, J);
        return J(0, 0);
      });
      time("JtF", [&](std::size_t k) {
        pinocchio::computeFrameJacobian(model, data, qs[k], hand, pinocchio::LOCAL_WORLD_ALIGNED, J);
        JtF.noalias() = J.transpose() * as[k].head<6>();
        return JtF[0];
      });
    }
    time("dtau", [&](std::size_t k) {
      pinocchio::computeRNEADerivatives(model, data, qs[k], vs[k], as[k]);
      return data.dtau_dq(0, 0);
    });
    if (!tree)
    {
      time("Y", [&](std::size_t k) {
        return pinocchio::computeJointTorqueRegressor(model, data, qs[k], vs[k], as[k])(0, 0);
      });
      // Pinocchio has no base regressor: its user computes Y and keeps the independent columns
      // (found once, by a QR with column pivoting of Y stacked over the samples).
      const std::vector<Eigen::Index> base = base_columns(model, qs, vs, as);
      Eigen::MatrixXd Yb(model.nv, static_cast<Eigen::Index>(base.size()));
      time("YB", [&](std::size_t k) {
        const Eigen::MatrixXd & Y = pinocchio::computeJointTorqueRegressor(model, data, qs[k], vs[k], as[k]);
        for (std::size_t c = 0; c < base.size(); ++c)
          Yb.col(static_cast<Eigen::Index>(c)) = Y.col(base[c]);
        return Yb(0, 0);
      });
    }
    if (forward)
    {
      time_with("dqdd", taus, [&](std::size_t k) {
        pinocchio::computeABADerivatives(model, data, qs[k], vs[k], taus[k]);
        return data.ddq_dq(0, 0);
      });
      time_with("fd", taus, [&](std::size_t k) {
        return pinocchio::aba(model, data, qs[k], vs[k], taus[k])[0];
      });
      time("Minv", [&](std::size_t k) {
        return pinocchio::computeMinverse(model, data, qs[k])(0, 0);
      });
    }
    // The simplified models beside the exact functions of Pinocchio, at the same states; the C
    // headers have no simplified family yet: no C column.
    if (with_simplified)
    {
      auto simplified = [&](const char * function, auto && pin) {
        const GeneratedFunction f = generated->get(robot, function);
        auto gen = [&](std::size_t k) {
          f(qs[k].data(), vs[k].data(), as[k].data(), out.data());
          return out[0];
        };
        const auto [pin_ns, gen_ns] = median_ns_in_turn(ns, pin, gen, checksum);
        std::printf("%s\t%s\t%.1f\t%.1f\n", robot.c_str(), function, pin_ns, gen_ns);
        std::fflush(stdout);
      };
      simplified("tau_simplified", [&](std::size_t k) {
        return pinocchio::rnea(model, data, qs[k], vs[k], as[k])[0];
      });
      simplified("M_simplified", [&](std::size_t k) {
        return pinocchio::crba(model, data, qs[k])(0, 0);
      });
      simplified("g_simplified", [&](std::size_t k) {
        return pinocchio::computeGeneralizedGravity(model, data, qs[k])[0];
      });
    }
    // The batches, for the two robots of the throughput targets.
    if (with_generated && (robot == "puma560" || robot == "panda"))
      time_batches(robot, *generated, model, qs, vs, as, taus, forward, checksum);
  }
  std::fprintf(stderr, "checksum %.17g\n", checksum);
  return 0;
}
