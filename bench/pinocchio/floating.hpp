// Robots on a free-flying base (tests/data/floating/, issue 43): Solo 12, ANYmal B, the Unitree
// G1. Included by bench.cpp after its checks, timing protocol and `Generated`.
//
// A file with "floating_body" holds "pinocchio_model": the model Pinocchio's URDF loader built
// with `JointModelFreeFlyer` as its root joint, the free flyer first, then the joints in the
// generator's order (tests/data/floating/make.py), so that q = [x, y, z, qx, qy, qz, qw, joints]
// (nq = n + 7) and v, a, tau = [base twist or wrench in the base frame, joints] (nv = n + 6) are
// the same numbers on both sides. Its samples' quaternions are unit (normalised Gaussian 4-vectors),
// checked here: Pinocchio reads a quaternion as given, and so does the generated code.
//
// `run_floating` checks Pinocchio's rnea, crba (mirrored), nonLinearEffects and
// computeGeneralizedGravity against the file on every sample; then, where the generated library
// has the robot (bench/ffi: `tau`, `M`, `h`, `g`, reading nq values from q and nv from v and a),
// each generated function against Pinocchio's doubles on every sample (TOLERANCE); then times the
// four, Pinocchio and the generated code in turn: `robot<TAB>function<TAB>pinocchio_ns<TAB>generated_ns`
// (Pinocchio's column alone without the library). No C header or CasADi peer has them yet.
// The generated `M` is `mass_matrix_into`, which leaves the blocks between two legs as it finds
// them: it writes into a matrix of its own, zeroed once and kept (as Pinocchio's crba keeps
// data.M). Then `fd` (aba at the sample's (q, v, tau)) and `Minv` (computeMinverse, mirrored),
// and the batch rows `tau_batch` (rneaInParallel on one thread), `fd_batch` (abaInParallel),
// `M_batch`, `h_batch`, `Minv_batch`, `dtau_batch` (loops), per state (`time_floating_batches`).
// Then the derivatives, `dtau` and `dqdd` (run_floating_derivatives), the regressor `Y`
// (run_floating_regressor), and, where the robot has a `<robot>_contact_fd.json` beside its file,
// `contact_fd` (run_floating_contacts).

#include "pinocchio/algorithm/constrained-dynamics.hpp"

// The largest departure of a sample's quaternion from unit length that is taken as unit.
static const double UNIT_QUATERNION = 1e-12;

// A matrix's values row-major, one block after the other (the generated functions' layout).
static Eigen::VectorXd row_major(std::initializer_list<Eigen::MatrixXd> blocks)
{
  Eigen::Index size = 0;
  for (const Eigen::MatrixXd & m : blocks)
    size += m.size();
  Eigen::VectorXd values(size);
  Eigen::Index at = 0;
  for (const Eigen::MatrixXd & m : blocks)
    for (Eigen::Index i = 0; i < m.rows(); ++i)
      for (Eigen::Index j = 0; j < m.cols(); ++j)
        values[at++] = m(i, j);
  return values;
}

// The first derivatives, `dtau` and `dqdd` (bench/ffi's FloatingDynamicsDerivatives, where the
// generated library has them): Pinocchio's computeRNEADerivatives at (q, v, a) and
// computeABADerivatives at (q, v, tau), tau the sample's rnea(q, v, a) (as bench.cpp's fixed
// robots take it), its derivatives by q along the tangent (integrate) as the generated ones; the
// generated blocks row-major, dtau = [dtau_dq; dtau_dv], dqdd = [ddq_dq; ddq_dv; Minv mirrored],
// checked against Pinocchio's on every sample, then timed in turn as run_floating times the others.
static void run_floating_derivatives(
  const std::string & robot, const Model & model, Data & data, const json::Value & samples,
  const std::vector<Eigen::VectorXd> & qs, const std::vector<Eigen::VectorXd> & vs,
  const std::vector<Eigen::VectorXd> & as, const Generated * generated, double & checksum)
{
  if (generated && !generated->lookup(robot.c_str(), "dtau"))
    return;
  const std::size_t ns = qs.size(), nv = static_cast<std::size_t>(model.nv);
  std::vector<Eigen::VectorXd> taus;
  for (std::size_t s = 0; s < ns; ++s)
    taus.push_back(vecn(samples[s]["tau"]));
  std::vector<double> out(3 * nv * nv + 1);
  auto time = [&](const char * function, const std::vector<Eigen::VectorXd> & thirds, auto && pin_output, auto && pin_timed) {
    if (!generated)
    {
      std::printf("%s\t%s\t%.1f\n", robot.c_str(), function, median_ns(ns, pin_timed, checksum));
      std::fflush(stdout);
      return;
    }
    const GeneratedFunction f = generated->get(robot, function);
    for (std::size_t s = 0; s < ns; ++s)
    {
      const Eigen::VectorXd want = pin_output(s);
      std::fill(out.begin(), out.end(), std::numeric_limits<double>::quiet_NaN());
      f(qs[s].data(), vs[s].data(), thirds[s].data(), out.data());
      const auto size = static_cast<std::size_t>(want.size());
      if (!std::isnan(out[size]))
        throw std::runtime_error(robot + ": the generated " + function + " writes past its output");
      const Eigen::VectorXd got = Eigen::Map<const Eigen::VectorXd>(out.data(), want.size());
      check(robot, std::string(function) + " (generated)", got, want, s);
    }
    auto gen = [&](std::size_t k) {
      f(qs[k].data(), vs[k].data(), thirds[k].data(), out.data());
      return out[0];
    };
    const auto [pin_ns, gen_ns] = median_ns_in_turn(ns, pin_timed, gen, checksum);
    std::printf("%s\t%s\t%.1f\t%.1f\n", robot.c_str(), function, pin_ns, gen_ns);
    std::fflush(stdout);
  };
  time(
    "dtau", as,
    [&](std::size_t k) {
      pinocchio::computeRNEADerivatives(model, data, qs[k], vs[k], as[k]);
      return row_major({data.dtau_dq, data.dtau_dv});
    },
    [&](std::size_t k) {
      pinocchio::computeRNEADerivatives(model, data, qs[k], vs[k], as[k]);
      return data.dtau_dq(0, 0);
    });
  time(
    "dqdd", taus,
    [&](std::size_t k) {
      pinocchio::computeABADerivatives(model, data, qs[k], vs[k], taus[k]);
      return row_major({data.ddq_dq, data.ddq_dv, symmetric(data.Minv)});
    },
    [&](std::size_t k) {
      pinocchio::computeABADerivatives(model, data, qs[k], vs[k], taus[k]);
      return data.ddq_dq(0, 0);
    });
}

// The joint torque regressor `Y` (bench/ffi's FloatingDynamicsRegressor, where the generated
// library has it: Solo 12): Pinocchio's computeJointTorqueRegressor on the free flyer at
// (q, v, a), nv × 10 (n + 1), the free flyer's body first, then the joints' in the file's order
// (pinocchio_model's order, so the same columns); the generated one row-major, written in place
// as Pinocchio writes data.jointTorqueRegressor. Checked against Pinocchio's on every sample,
// then timed in turn. Without the generated library, Pinocchio's row alone for every robot.
static void run_floating_regressor(
  const std::string & robot, const Model & model, Data & data,
  const std::vector<Eigen::VectorXd> & qs, const std::vector<Eigen::VectorXd> & vs,
  const std::vector<Eigen::VectorXd> & as, const Generated * generated, double & checksum)
{
  if (generated && !generated->lookup(robot.c_str(), "Y"))
    return;
  const std::size_t ns = qs.size();
  auto pin_timed = [&](std::size_t k) {
    return pinocchio::computeJointTorqueRegressor(model, data, qs[k], vs[k], as[k])(0, 0);
  };
  if (!generated)
  {
    std::printf("%s\tY\t%.1f\n", robot.c_str(), median_ns(ns, pin_timed, checksum));
    std::fflush(stdout);
    return;
  }
  const GeneratedFunction f = generated->get(robot, "Y");
  const Eigen::Index rows = model.nv, columns = 10 * (model.njoints - 1);
  std::vector<double> out(static_cast<std::size_t>(rows * columns) + 1);
  for (std::size_t s = 0; s < ns; ++s)
  {
    std::fill(out.begin(), out.end(), std::numeric_limits<double>::quiet_NaN());
    f(qs[s].data(), vs[s].data(), as[s].data(), out.data());
    if (!std::isnan(out[static_cast<std::size_t>(rows * columns)]))
      throw std::runtime_error(robot + ": the generated Y writes past its output");
    // Row-major: the transpose of a column-major columns × rows map.
    const Eigen::MatrixXd got = Eigen::Map<const Eigen::MatrixXd>(out.data(), columns, rows).transpose();
    const Eigen::MatrixXd want = pinocchio::computeJointTorqueRegressor(model, data, qs[s], vs[s], as[s]);
    check(robot, "Y (generated)", got, want, s);
  }
  auto gen = [&](std::size_t k) {
    f(qs[k].data(), vs[k].data(), as[k].data(), out.data());
    return out[0];
  };
  const auto [pin_ns, gen_ns] = median_ns_in_turn(ns, pin_timed, gen, checksum);
  std::printf("%s\tY\t%.1f\t%.1f\n", robot.c_str(), pin_ns, gen_ns);
  std::fflush(stdout);
}

// The batch rows of a robot on a free-flying base, per state: a horizon of `gen.horizon()`
// states (the samples in turn, nq values of q and nv of the others per state) in one call of
// the generated `_batch` functions, beside Pinocchio's own batch on one thread of a ModelPool
// (`tau_batch`: rneaInParallel, `fd_batch`: abaInParallel) or, where it has none, a loop of its
// single-state function (`M_batch`: crba, `h_batch`: nonLinearEffects, `Minv_batch`:
// computeMinverse, `dtau_batch`: computeRNEADerivatives), as the fixed robots' batches
// (bench.cpp's time_batches). Each state's generated output is checked first against the
// generated single-state function's and, for the rows of the loops, against Pinocchio's at that
// state (M and Minv mirrored, dtau = [dtau_dq; dtau_dv]). A row the library lacks is left out.
static void time_floating_batches(
  const std::string & robot,
  const Generated & gen,
  const Model & model,
  const std::vector<Eigen::VectorXd> & qs,
  const std::vector<Eigen::VectorXd> & vs,
  const std::vector<Eigen::VectorXd> & as,
  const std::vector<Eigen::VectorXd> & taus,
  double & checksum)
{
  const Eigen::Index nq = model.nq, n = model.nv, h = static_cast<Eigen::Index>(gen.horizon());
  Eigen::MatrixXd Q(nq, h), V(n, h), A(n, h), TAU(n, h), OUT(n, h);
  for (Eigen::Index k = 0; k < h; ++k)
  {
    const std::size_t s = static_cast<std::size_t>(k) % qs.size();
    Q.col(k) = qs[s], V.col(k) = vs[s], A.col(k) = as[s], TAU.col(k) = taus[s];
  }
  Data data(model);
  // Pinocchio's output at state k of the horizon, row-major, for the rows it has no batch of.
  using Reference = std::function<Eigen::VectorXd(Eigen::Index)>;
  const Reference none;
  const Reference mass = [&](Eigen::Index k) { return row_major({symmetric(pinocchio::crba(model, data, Q.col(k)))}); };
  const Reference bias = [&](Eigen::Index k) {
    return Eigen::VectorXd(pinocchio::nonLinearEffects(model, data, Q.col(k), V.col(k)));
  };
  const Reference inverse = [&](Eigen::Index k) {
    return row_major({symmetric(pinocchio::computeMinverse(model, data, Q.col(k)))});
  };
  const Reference derivatives = [&](Eigen::Index k) {
    pinocchio::computeRNEADerivatives(model, data, Q.col(k), V.col(k), A.col(k));
    return row_major({data.dtau_dq, data.dtau_dv});
  };
  struct Batch
  {
    const char * batch, * single;
    const Eigen::MatrixXd * third;
    Eigen::Index size;
    const Reference * pinocchio;
  };
  const std::vector<Batch> batches = {
    {"tau_batch", "tau", &A, n, &none},           {"fd_batch", "fd", &TAU, n, &none},
    {"M_batch", "M", &A, n * n, &mass},           {"h_batch", "h", &A, n, &bias},
    {"Minv_batch", "Minv", &A, n * n, &inverse},  {"dtau_batch", "dtau", &A, 2 * n * n, &derivatives}};
  // Room for the largest output, dtau's, and one more value, which no function may write.
  std::vector<double> out(static_cast<std::size_t>(2 * n * n * h + 1)), one(static_cast<std::size_t>(2 * n * n));
  for (const Batch & b : batches)
  {
    if (!gen.lookup(robot.c_str(), b.batch))
      continue;
    std::fill(out.begin(), out.end(), std::numeric_limits<double>::quiet_NaN());
    gen.get(robot, b.batch)(Q.data(), V.data(), b.third->data(), out.data());
    if (!std::isnan(out[static_cast<std::size_t>(b.size * h)]))
      throw std::runtime_error(robot + ": the generated " + b.batch + " writes past its output");
    for (Eigen::Index k = 0; k < h; ++k)
    {
      // Zeros first: the single-state `M` leaves the blocks between two legs as it finds them.
      std::fill(one.begin(), one.end(), 0.0);
      gen.get(robot, b.single)(Q.col(k).data(), V.col(k).data(), b.third->col(k).data(), one.data());
      const Eigen::Map<const Eigen::VectorXd> got(out.data() + k * b.size, b.size), want(one.data(), b.size);
      const std::string state = std::string(b.batch) + " state " + std::to_string(k);
      check(robot, state, got, want, static_cast<std::size_t>(k));
      if (*b.pinocchio)
        check(robot, state + " (Pinocchio's)", got, (*b.pinocchio)(k), static_cast<std::size_t>(k));
    }
  }
  pinocchio::ModelPool pool(model, 1);
  const int warmup = 100, calls = 200;
  auto row = [&](const char * function, const Eigen::MatrixXd & third, auto && pin) {
    if (!gen.lookup(robot.c_str(), function))
      return;
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
  // Pinocchio's loop over the horizon of `one(k)`, one element of each state's output summed.
  auto loop = [&](auto && one) {
    return [&, one] {
      double sum = 0.0;
      for (Eigen::Index k = 0; k < h; ++k)
        sum += one(k);
      return sum;
    };
  };
  row("tau_batch", A, [&] {
    pinocchio::rneaInParallel(1, pool, Q, V, A, OUT);
    return OUT(0, 0);
  });
  row("fd_batch", TAU, [&] {
    pinocchio::abaInParallel(1, pool, Q, V, TAU, OUT);
    return OUT(0, 0);
  });
  row("M_batch", A, loop([&](Eigen::Index k) { return pinocchio::crba(model, data, Q.col(k))(0, 0); }));
  row("h_batch", A, loop([&](Eigen::Index k) { return pinocchio::nonLinearEffects(model, data, Q.col(k), V.col(k))[0]; }));
  row("Minv_batch", A, loop([&](Eigen::Index k) { return pinocchio::computeMinverse(model, data, Q.col(k))(0, 0); }));
  row("dtau_batch", A, loop([&](Eigen::Index k) {
        pinocchio::computeRNEADerivatives(model, data, Q.col(k), V.col(k), A.col(k));
        return data.dtau_dq(0, 0);
      }));
}

// `contact_fd`: constraintDynamics with every foot of `<robot>_contact_fd.json` held (a
// RigidConstraintModel CONTACT_3D in LOCAL_WORLD_ALIGNED on the foot's joint at its placement, no
// Baumgarte; initConstraintDynamics once) at the samples' (q, v, tau), beside the generated
// FloatingContacts::contact_dynamics with every frame in contact (bench/ffi: [a; lambda], lambda
// a row of 3 per foot). Pinocchio's checked against the file, the generated against Pinocchio's,
// then both timed in turn.
static void run_floating_contacts(
  const std::string & robot, const std::string & path, const Model & model,
  const std::vector<Eigen::VectorXd> & qs, const std::vector<Eigen::VectorXd> & vs,
  const std::vector<Eigen::VectorXd> & taus, const Generated * generated, double & checksum)
{
  const std::string contact_path = path.substr(0, path.rfind(".json")) + "_contact_fd.json";
  if (!std::ifstream(contact_path).good())
    return;
  const json::Value file = json::parse_file(contact_path);
  const json::Value & frames = file["frames"], & samples = file["samples"];
  if (samples.size() != qs.size())
    throw std::runtime_error(robot + ": " + contact_path + " has not a sample per state");
  pinocchio::RigidConstraintModelVector models;
  for (std::size_t f = 0; f < frames.size(); ++f)
  {
    const json::Value & frame = frames[f];
    Eigen::Matrix3d R;
    for (Eigen::Index r = 0; r < 3; ++r)
      for (Eigen::Index c = 0; c < 3; ++c)
        R(r, c) = frame["rotation"][static_cast<std::size_t>(r)][static_cast<std::size_t>(c)].number();
    const std::string joint = frame["joint"].string();
    if (!model.existJointName(joint))
      throw std::runtime_error(robot + ": no joint " + joint + " for the foot " + frame["name"].string());
    models.emplace_back(
      pinocchio::CONTACT_3D, model, model.getJointId(joint), SE3(R, vec3(frame["translation"])),
      pinocchio::LOCAL_WORLD_ALIGNED);
  }
  pinocchio::RigidConstraintDataVector datas;
  for (const auto & m : models)
    datas.emplace_back(m);
  Data data(model);
  pinocchio::initConstraintDynamics(model, data, models, datas);
  pinocchio::ProximalSettings settings;
  const std::size_t ns = qs.size(), nv = static_cast<std::size_t>(model.nv), nc = 3 * frames.size();
  auto pin_output = [&](std::size_t k) {
    pinocchio::constraintDynamics(model, data, qs[k], vs[k], taus[k], models, datas, settings);
    Eigen::VectorXd out(nv + nc);
    out << data.ddq, data.lambda_c;
    return out;
  };
  for (std::size_t s = 0; s < ns; ++s)
  {
    // lambda a row of 3 per foot, one after the other (data.lambda_c's order).
    const Eigen::MatrixXd lambda = matn(samples[s]["lambda"]).transpose();
    Eigen::VectorXd want(nv + nc);
    want << vecn(samples[s]["a_contact"]), Eigen::Map<const Eigen::VectorXd>(lambda.data(), lambda.size());
    check(robot, "constraintDynamics", pin_output(s), want, s);
  }
  auto pin_timed = [&](std::size_t k) {
    return pinocchio::constraintDynamics(model, data, qs[k], vs[k], taus[k], models, datas, settings)[0];
  };
  if (!generated || !generated->lookup(robot.c_str(), "contact_fd"))
  {
    std::printf("%s\tcontact_fd\t%.1f\n", robot.c_str(), median_ns(ns, pin_timed, checksum));
    std::fflush(stdout);
    return;
  }
  const GeneratedFunction f = generated->get(robot, "contact_fd");
  std::vector<double> out(nv + nc + 1);
  for (std::size_t s = 0; s < ns; ++s)
  {
    std::fill(out.begin(), out.end(), std::numeric_limits<double>::quiet_NaN());
    f(qs[s].data(), vs[s].data(), taus[s].data(), out.data());
    if (!std::isnan(out[nv + nc]))
      throw std::runtime_error(robot + ": the generated contact_fd writes past its output");
    const Eigen::VectorXd got = Eigen::Map<const Eigen::VectorXd>(out.data(), static_cast<Eigen::Index>(nv + nc));
    check(robot, "contact_fd (generated)", got, pin_output(s), s);
  }
  auto gen = [&](std::size_t k) {
    f(qs[k].data(), vs[k].data(), taus[k].data(), out.data());
    return out[0];
  };
  const auto [pin_ns, gen_ns] = median_ns_in_turn(ns, pin_timed, gen, checksum);
  std::printf("%s\tcontact_fd\t%.1f\t%.1f\n", robot.c_str(), pin_ns, gen_ns);
  std::fflush(stdout);
}

static void run_floating(const std::string & robot, const json::Value & file, const std::string & path, const Generated * generated, double & checksum)
{
  const Model model = build_model_from_pinocchio(file["pinocchio_model"]);
  if (model.joints[1].shortname() != "JointModelFreeFlyer")
    throw std::runtime_error(robot + ": the first joint of pinocchio_model is not a free flyer");
  Data data(model);
  const json::Value & samples = file["samples"];
  std::vector<Eigen::VectorXd> qs, vs, as;
  for (std::size_t s = 0; s < samples.size(); ++s)
  {
    const json::Value & x = samples[s];
    qs.push_back(vecn(x["q"]));
    vs.push_back(vecn(x["v"]));
    as.push_back(vecn(x["a"]));
    if (qs[s].size() != model.nq || vs[s].size() != model.nv || as[s].size() != model.nv)
      throw std::runtime_error(robot + ": sample " + std::to_string(s) + " has the wrong lengths");
    if (std::abs(qs[s].segment<4>(3).norm() - 1.0) > UNIT_QUATERNION)
      throw std::runtime_error(robot + ": sample " + std::to_string(s) + "'s quaternion is not unit");
    check(robot, "rnea", pinocchio::rnea(model, data, qs[s], vs[s], as[s]), vecn(x["tau"]), s);
    check(robot, "crba", symmetric(pinocchio::crba(model, data, qs[s])), matn(x["M"]), s);
    check(robot, "nonLinearEffects", pinocchio::nonLinearEffects(model, data, qs[s], vs[s]), vecn(x["h"]), s);
    check(robot, "computeGeneralizedGravity", pinocchio::computeGeneralizedGravity(model, data, qs[s]), vecn(x["g"]), s);
  }
  const std::size_t ns = qs.size(), nv = static_cast<std::size_t>(model.nv);
  const bool with_generated = generated && generated->dof(robot.c_str()) != 0;
  if (generated && !with_generated)
    std::fprintf(stderr, "%s: not in the generated library: Pinocchio alone\n", robot.c_str());
  if (with_generated && generated->dof(robot.c_str()) != nv)
    throw std::runtime_error(robot + ": the generated library's dof is not the model's nv");
  // Room for M (nv × nv) and one more value, which no function may write.
  std::vector<double> out(nv * nv + 1);
  std::vector<Eigen::VectorXd> taus;
  for (std::size_t s = 0; s < ns; ++s)
    taus.push_back(vecn(samples[s]["tau"]));
  // Pinocchio's `function` (its output at sample k as a row-major vector, for the check, and one
  // element of it, timed), beside the generated one where it is loaded.
  // `function` reads `third` (the accelerations, or the torques of `fd`) as its third input.
  auto time_with = [&](const char * function, const std::vector<Eigen::VectorXd> & third, auto && pin_output, auto && pin_timed) {
    if (!with_generated)
    {
      std::printf("%s\t%s\t%.1f\n", robot.c_str(), function, median_ns(ns, pin_timed, checksum));
      std::fflush(stdout);
      return;
    }
    const GeneratedFunction f = generated->get(robot, function);
    // `M` keeps its matrix, zeroed once; every other output starts as NaN.
    const bool kept = std::string(function) == "M";
    std::fill(out.begin(), out.end(), kept ? 0.0 : std::numeric_limits<double>::quiet_NaN());
    for (std::size_t s = 0; s < ns; ++s)
    {
      const Eigen::VectorXd want = pin_output(s);
      if (!kept)
        std::fill(out.begin(), out.end(), std::numeric_limits<double>::quiet_NaN());
      out[nv * nv] = std::numeric_limits<double>::quiet_NaN();
      f(qs[s].data(), vs[s].data(), third[s].data(), out.data());
      const auto size = static_cast<std::size_t>(want.size());
      if (!std::isnan(out[size]))
        throw std::runtime_error(robot + ": the generated " + function + " writes past its output");
      const Eigen::VectorXd got = Eigen::Map<const Eigen::VectorXd>(out.data(), want.size());
      check(robot, std::string(function) + " (generated)", got, want, s);
    }
    auto gen = [&](std::size_t k) {
      f(qs[k].data(), vs[k].data(), third[k].data(), out.data());
      return out[0];
    };
    const auto [pin_ns, gen_ns] = median_ns_in_turn(ns, pin_timed, gen, checksum);
    std::printf("%s\t%s\t%.1f\t%.1f\n", robot.c_str(), function, pin_ns, gen_ns);
    std::fflush(stdout);
  };
  auto time = [&](const char * function, auto && pin_output, auto && pin_timed) {
    time_with(function, as, pin_output, pin_timed);
  };
  // M row-major (symmetric, so its transpose's column-major storage is the same numbers).
  auto mass = [&](std::size_t k) {
    const Eigen::MatrixXd m = symmetric(pinocchio::crba(model, data, qs[k]));
    return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(m.data(), m.size()));
  };
  time(
    "tau",
    [&](std::size_t k) { return Eigen::VectorXd(pinocchio::rnea(model, data, qs[k], vs[k], as[k])); },
    [&](std::size_t k) { return pinocchio::rnea(model, data, qs[k], vs[k], as[k])[0]; });
  time("M", mass, [&](std::size_t k) { return pinocchio::crba(model, data, qs[k])(0, 0); });
  time(
    "h",
    [&](std::size_t k) { return Eigen::VectorXd(pinocchio::nonLinearEffects(model, data, qs[k], vs[k])); },
    [&](std::size_t k) { return pinocchio::nonLinearEffects(model, data, qs[k], vs[k])[0]; });
  time(
    "g",
    [&](std::size_t k) { return Eigen::VectorXd(pinocchio::computeGeneralizedGravity(model, data, qs[k])); },
    [&](std::size_t k) { return pinocchio::computeGeneralizedGravity(model, data, qs[k])[0]; });
  // The forward dynamics, M⁻¹, and the batches.
  time_with(
    "fd", taus,
    [&](std::size_t k) { return Eigen::VectorXd(pinocchio::aba(model, data, qs[k], vs[k], taus[k])); },
    [&](std::size_t k) { return pinocchio::aba(model, data, qs[k], vs[k], taus[k])[0]; });
  time(
    "Minv",
    [&](std::size_t k) {
      const Eigen::MatrixXd m = symmetric(pinocchio::computeMinverse(model, data, qs[k]));
      return Eigen::VectorXd(Eigen::Map<const Eigen::VectorXd>(m.data(), m.size()));
    },
    [&](std::size_t k) { return pinocchio::computeMinverse(model, data, qs[k])(0, 0); });
  if (with_generated)
    time_floating_batches(robot, *generated, model, qs, vs, as, taus, checksum);
  run_floating_derivatives(robot, model, data, samples, qs, vs, as, with_generated ? generated : nullptr, checksum);
  run_floating_regressor(robot, model, data, qs, vs, as, with_generated ? generated : nullptr, checksum);
  run_floating_contacts(robot, path, model, qs, vs, taus, with_generated ? generated : nullptr, checksum);
}
