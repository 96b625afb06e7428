// The generated-code peer of the side-by-side benchmark (see bench/README.md; driven by bench/run):
// Pinocchio's own algorithms evaluated on CasADi's symbolic scalar (casadi::SX, through
// pinocchio/autodiff/casadi.hpp) and exported as C by CasADi's code generator.
//
// Usage: casadi_generate OUTDIR DATA.json [DATA.json ...]
//
// For each reference data file (the same files, and the same models, as bench/pinocchio/bench.cpp:
// model.hpp builds both) the program casts the robot's Pinocchio model to casadi::SX, traces
//   tau   rnea(model, data, q, v, a)                       n values
//   M     crba(model, data, q), its upper triangle mirrored   n × n, row-major
//   dtau  computeRNEADerivatives(model, data, q, v, a)     ∂τ/∂q, ∂τ/∂q̇: 2 n × n, row-major
//   dqdd  computeABADerivatives(model, data, q, v, tau)    ∂q̈/∂q, ∂q̈/∂q̇, M⁻¹: 3 n × n, row-major
// (`dqdd` only where the file's M is positive definite at every sample, as bench.cpp times it),
// the outputs laid out as bench/ffi's functions write theirs, each into a casadi::Function of
// (q, v, third), in three variants, the peer's best being whichever runs fastest
// (bench.cpp picks it per function):
//   plain  CasADi's default options;
//   cse    common subexpressions eliminated ("cse");
//   snap   "cse" on a model whose constants within 1e-15 of 0, 1 or -1 (the rotations'
//          cos(π/2) = 6.1e-17 above all) are those exactly, so that CasADi's construction-time
//          simplifications (x · 0, x · 1, x + 0) drop what they multiply or add.
// It writes
//   OUTDIR/ROBOT_VARIANT_FUNCTION.c   CasADi's C code of the function (CodeGenerator), and
//   OUTDIR/ROBOT.c            casadi_bench_ROBOT("FUNCTION:VARIANT"): the function behind
//                             bench.cpp's signature f(q, v, third, out), its work arrays static,
//                             or null.
// A file whose text is unchanged is not rewritten, so that its object is not rebuilt. The time
// each robot's tracing and code generation took goes to stderr.

#include "pinocchio/autodiff/casadi.hpp"

#include "../pinocchio/model.hpp"

#include "pinocchio/algorithm/aba-derivatives.hpp"
#include "pinocchio/algorithm/crba.hpp"
#include "pinocchio/algorithm/rnea-derivatives.hpp"
#include "pinocchio/algorithm/rnea.hpp"

#include <chrono>
#include <cstdio>

using SX = casadi::SX;
using ModelSX = pinocchio::ModelTpl<SX>;
using DataSX = pinocchio::DataTpl<SX>;
using VectorSX = Eigen::Matrix<SX, Eigen::Dynamic, 1>;
using MatrixSX = Eigen::Matrix<SX, Eigen::Dynamic, Eigen::Dynamic>;

// Writes `text` to `path` unless the file already holds it.
static void write_if_changed(const std::string & path, const std::string & text)
{
  std::ifstream in(path, std::ios::binary);
  if (in)
  {
    std::stringstream old;
    old << in.rdbuf();
    if (old.str() == text)
      return;
  }
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out)
    throw std::runtime_error("cannot write " + path);
}

// The n scalars of a symbolic column as an Eigen vector.
static VectorSX entries(const SX & x)
{
  VectorSX v(x.size1());
  for (Eigen::Index i = 0; i < v.size(); ++i)
    v[i] = x(static_cast<casadi_int>(i));
  return v;
}

// Matrices one after the other, each row-major, as one column (bench/ffi's layout). With
// `mirror`, a matrix's strict lower triangle is read from its upper one (crba and
// computeABADerivatives fill M and M⁻¹'s upper triangle only).
static SX rows_of(const std::vector<std::pair<const MatrixSX *, bool>> & blocks)
{
  std::vector<SX> values;
  for (const auto & [m, mirror] : blocks)
    for (Eigen::Index r = 0; r < m->rows(); ++r)
      for (Eigen::Index c = 0; c < m->cols(); ++c)
        values.push_back(mirror && r > c ? (*m)(c, r) : (*m)(r, c));
  return SX::vertcat(values);
}

struct Traced
{
  std::string name; // the function's name in bench.cpp's lookup (tau:cse, M:snap, ...)
  casadi::Function f;
};

// `x` made exactly 0, 1 or -1 where it is within 1e-15 of one of them.
static void snap(double & x)
{
  for (const double exact : {0.0, 1.0, -1.0})
    if (std::abs(x - exact) <= 1e-15)
      x = exact;
}

// Every entry of a fixed-size Eigen matrix snapped.
template<typename Matrix>
static void snap_all(Matrix && m)
{
  for (Eigen::Index i = 0; i < m.size(); ++i)
    snap(m.data()[i]);
}

// The model with its joints' placements and its bodies' inertias snapped (`snap`).
static pinocchio::Model snapped(pinocchio::Model model)
{
  for (auto & placement : model.jointPlacements)
  {
    snap_all(placement.rotation());
    snap_all(placement.translation());
  }
  for (auto & inertia : model.inertias)
  {
    snap(inertia.mass());
    snap_all(inertia.lever());
    snap_all(inertia.inertia().data());
  }
  return model;
}

// The four functions of a robot, traced through Pinocchio's algorithms on casadi::SX, each in
// the variants of `variants` (name and CasADi options) on the model as given.
static std::vector<Traced> trace(
  const std::string & robot,
  const pinocchio::Model & model,
  bool forward,
  const std::vector<std::pair<std::string, casadi::Dict>> & variants)
{
  const ModelSX m = model.cast<SX>();
  DataSX data(m);
  const casadi_int n = model.nv;
  const SX q = SX::sym("q", n), v = SX::sym("v", n), third = SX::sym("third", n);
  const VectorSX qe = entries(q), ve = entries(v), te = entries(third);
  std::vector<Traced> out;
  auto add = [&](const std::string & name, const SX & result) {
    // Dense: a structural zero would otherwise be left out of the output, moving its successors.
    for (const auto & [variant, options] : variants)
      out.push_back(
        {name + ":" + variant,
         casadi::Function(robot + "_" + variant + "_" + name, {q, v, third}, {SX::densify(result)}, options)});
  };
  pinocchio::rnea(m, data, qe, ve, te);
  add("tau", SX::vertcat(std::vector<SX>(data.tau.data(), data.tau.data() + n)));
  const MatrixSX M = pinocchio::crba(m, data, qe);
  add("M", rows_of({{&M, true}}));
  pinocchio::computeRNEADerivatives(m, data, qe, ve, te);
  const MatrixSX dtau_dq = data.dtau_dq, dtau_dv = data.dtau_dv;
  add("dtau", rows_of({{&dtau_dq, false}, {&dtau_dv, false}}));
  if (forward)
  {
    pinocchio::computeABADerivatives(m, data, qe, ve, te);
    const MatrixSX ddq_dq = data.ddq_dq, ddq_dv = data.ddq_dv, Minv = data.Minv;
    add("dqdd", rows_of({{&ddq_dq, false}, {&ddq_dv, false}, {&Minv, true}}));
  }
  return out;
}

// ROBOT.c: per function, a wrapper of bench.cpp's signature around CasADi's calling convention
// (argument and result pointer arrays, integer and real work arrays), and the lookup.
static std::string lookup_source(const std::string & robot, const std::vector<Traced> & functions)
{
  std::ostringstream s;
  s << "/* The CasADi-traced Pinocchio functions of " << robot
    << " behind bench.cpp's signature (written by bench/casadi/generate.cpp). */\n"
    << "#include <string.h>\n\n";
  for (const auto & t : functions)
  {
    const std::string name = t.f.name();
    // CasADi's default casadi_int is long long int.
    s << "int " << name << "(const double ** arg, double ** res, long long int * iw, double * w, int mem);\n"
      << "static void call_" << name << "(const double * q, const double * v, const double * third, double * out)\n"
      << "{\n"
      << "  static long long int iw[" << std::max<casadi_int>(1, t.f.sz_iw()) << "];\n"
      << "  static double w[" << std::max<casadi_int>(1, t.f.sz_w()) << "];\n"
      << "  const double * arg[" << std::max<casadi_int>(3, t.f.sz_arg()) << "] = {q, v, third};\n"
      << "  double * res[" << std::max<casadi_int>(1, t.f.sz_res()) << "] = {out};\n"
      << "  " << name << "(arg, res, iw, w, 0);\n"
      << "}\n\n";
  }
  s << "typedef void (*casadi_bench_fn)(const double *, const double *, const double *, double *);\n"
    << "casadi_bench_fn casadi_bench_" << robot << "(const char * function)\n{\n";
  for (const auto & t : functions)
    s << "  if (strcmp(function, \"" << t.name << "\") == 0)\n    return call_" << t.f.name() << ";\n";
  s << "  return 0;\n}\n";
  return s.str();
}

// Whether the file's M is positive definite at every sample (bench.cpp's `invertible`).
static bool invertible(const json::Value & samples)
{
  for (std::size_t s = 0; s < samples.size(); ++s)
    if (Eigen::LLT<Eigen::MatrixXd>(matn(samples[s]["M"])).info() != Eigen::Success)
      return false;
  return true;
}

int main(int argc, char ** argv)
{
  if (argc < 3)
  {
    std::fprintf(stderr, "usage: %s OUTDIR DATA.json [DATA.json ...]\n", argv[0]);
    return 2;
  }
  const std::string dir = argv[1];
  for (int arg = 2; arg < argc; ++arg)
  {
    const std::string path = argv[arg];
    try
    {
      const auto t0 = std::chrono::steady_clock::now();
      const json::Value file = json::parse_file(path);
      const std::string robot = file["robot"].string();
      pinocchio::Model model;
      if (file.has("pinocchio_model"))
        model = build_model_from_pinocchio(file["pinocchio_model"]);
      else
      {
        SE3 hand;
        std::vector<SE3> links;
        model = build_model(file["description"], hand, links);
      }
      const bool forward = invertible(file["samples"]);
      const casadi::Dict plain, cse = {{"cse", true}};
      std::vector<Traced> functions = trace(robot, model, forward, {{"plain", plain}, {"cse", cse}});
      for (Traced & t : trace(robot, snapped(model), forward, {{"snap", cse}}))
        functions.push_back(std::move(t));
      for (const auto & t : functions)
      {
        casadi::CodeGenerator gen(t.f.name() + ".c");
        gen.add(t.f);
        write_if_changed(dir + "/" + t.f.name() + ".c", gen.dump());
      }
      write_if_changed(dir + "/" + robot + ".c", lookup_source(robot, functions));
      const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::fprintf(stderr, "%s: traced and generated in %.1f s:", robot.c_str(), s);
      for (const auto & t : functions)
        std::fprintf(stderr, " %s %lld operations", t.name.c_str(), static_cast<long long>(t.f.n_instructions()));
      std::fprintf(stderr, "\n");
    }
    catch (const std::exception & e)
    {
      std::fprintf(stderr, "%s: %s\n", path.c_str(), e.what());
      return 1;
    }
  }
  return 0;
}
