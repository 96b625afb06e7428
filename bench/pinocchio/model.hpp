// The robots of the side-by-side benchmark as Pinocchio models, shared by bench.cpp and
// bench/casadi/generate.cpp: a minimal JSON reader for the reference data files, the model of a
// D-H description or of the model Pinocchio's URDF loader built, and vectors and matrices of JSON.
// Include it after any autodiff header of Pinocchio (pinocchio/autodiff/casadi.hpp goes first).

#pragma once

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "pinocchio/multibody.hpp"

// ---------------------------------------------------------------------------------------------
// Minimal JSON reader: null, booleans, numbers, strings, arrays, objects. Enough for the
// reference data files; not a general-purpose validating parser.
// ---------------------------------------------------------------------------------------------

namespace json
{
  struct Value
  {
    enum Kind
    {
      Null,
      Bool,
      Number,
      String,
      Array,
      Object
    } kind = Null;
    bool b = false;
    double num = 0.0;
    std::string str;
    std::vector<Value> arr;
    std::map<std::string, Value> obj;

    const Value & operator[](const std::string & key) const
    {
      if (kind != Object)
        throw std::runtime_error("JSON: not an object (looking up \"" + key + "\")");
      auto it = obj.find(key);
      if (it == obj.end())
        throw std::runtime_error("JSON: missing key \"" + key + "\"");
      return it->second;
    }
    const Value & operator[](std::size_t i) const
    {
      if (kind != Array)
        throw std::runtime_error("JSON: not an array");
      if (i >= arr.size())
        throw std::runtime_error("JSON: index out of range");
      return arr[i];
    }
    bool has(const std::string & key) const
    {
      return kind == Object && obj.count(key) != 0;
    }
    std::size_t size() const
    {
      if (kind != Array)
        throw std::runtime_error("JSON: not an array");
      return arr.size();
    }
    double number() const
    {
      if (kind != Number)
        throw std::runtime_error("JSON: not a number");
      return num;
    }
    const std::string & string() const
    {
      if (kind != String)
        throw std::runtime_error("JSON: not a string");
      return str;
    }
  };

  class Parser
  {
  public:
    explicit Parser(const std::string & text)
    : s(text)
    {
    }

    Value parse()
    {
      Value v = value();
      ws();
      if (pos != s.size())
        fail("trailing characters");
      return v;
    }

  private:
    const std::string & s;
    std::size_t pos = 0;

    [[noreturn]] void fail(const std::string & what) const
    {
      throw std::runtime_error("JSON parse error at byte " + std::to_string(pos) + ": " + what);
    }
    void ws()
    {
      while (pos < s.size() && std::isspace(static_cast<unsigned char>(s[pos])))
        ++pos;
    }
    char peek()
    {
      ws();
      if (pos >= s.size())
        fail("unexpected end of input");
      return s[pos];
    }
    void expect(char c)
    {
      if (peek() != c)
        fail(std::string("expected '") + c + "'");
      ++pos;
    }
    bool literal(const char * word)
    {
      std::size_t len = std::char_traits<char>::length(word);
      if (s.compare(pos, len, word) == 0)
      {
        pos += len;
        return true;
      }
      return false;
    }

    Value value()
    {
      Value v;
      char c = peek();
      if (c == '{')
      {
        v.kind = Value::Object;
        ++pos;
        if (peek() == '}')
        {
          ++pos;
          return v;
        }
        for (;;)
        {
          if (peek() != '"')
            fail("expected a string key");
          std::string key = string();
          expect(':');
          v.obj[key] = value();
          char d = peek();
          ++pos;
          if (d == '}')
            break;
          if (d != ',')
            fail("expected ',' or '}'");
        }
      }
      else if (c == '[')
      {
        v.kind = Value::Array;
        ++pos;
        if (peek() == ']')
        {
          ++pos;
          return v;
        }
        for (;;)
        {
          v.arr.push_back(value());
          char d = peek();
          ++pos;
          if (d == ']')
            break;
          if (d != ',')
            fail("expected ',' or ']'");
        }
      }
      else if (c == '"')
      {
        v.kind = Value::String;
        v.str = string();
      }
      else if (literal("true"))
      {
        v.kind = Value::Bool;
        v.b = true;
      }
      else if (literal("false"))
      {
        v.kind = Value::Bool;
      }
      else if (literal("null"))
      {
        v.kind = Value::Null;
      }
      else
      {
        const char * begin = s.c_str() + pos;
        char * end = nullptr;
        v.kind = Value::Number;
        v.num = std::strtod(begin, &end);
        if (end == begin)
          fail("unexpected character");
        pos += static_cast<std::size_t>(end - begin);
      }
      return v;
    }

    std::string string()
    {
      expect('"');
      std::string out;
      while (pos < s.size() && s[pos] != '"')
      {
        char c = s[pos++];
        if (c == '\\')
        {
          if (pos >= s.size())
            fail("unterminated escape");
          char e = s[pos++];
          switch (e)
          {
          case 'n':
            out += '\n';
            break;
          case 't':
            out += '\t';
            break;
          case 'r':
            out += '\r';
            break;
          case 'b':
            out += '\b';
            break;
          case 'f':
            out += '\f';
            break;
          case 'u': // code point not needed here: keep a placeholder
            if (pos + 4 > s.size())
              fail("bad \\u escape");
            pos += 4;
            out += '?';
            break;
          default: // '"', '\\', '/'
            out += e;
          }
        }
        else
          out += c;
      }
      if (pos >= s.size())
        fail("unterminated string");
      ++pos;
      return out;
    }
  };

  Value parse_file(const std::string & path)
  {
    std::ifstream in(path, std::ios::binary);
    if (!in)
      throw std::runtime_error("cannot open " + path);
    std::stringstream buf;
    buf << in.rdbuf();
    std::string text = buf.str();
    return Parser(text).parse();
  }
} // namespace json

// ---------------------------------------------------------------------------------------------
// Model from a D-H description
// ---------------------------------------------------------------------------------------------

using pinocchio::Data;
using pinocchio::Inertia;
using pinocchio::Model;
using pinocchio::SE3;

static SE3 rotz(double t)
{
  return SE3(Eigen::AngleAxisd(t, Eigen::Vector3d::UnitZ()).toRotationMatrix(), Eigen::Vector3d::Zero());
}
static SE3 rotx(double t)
{
  return SE3(Eigen::AngleAxisd(t, Eigen::Vector3d::UnitX()).toRotationMatrix(), Eigen::Vector3d::Zero());
}
static SE3 transz(double d)
{
  return SE3(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, d));
}
static SE3 transx(double a)
{
  return SE3(Eigen::Matrix3d::Identity(), Eigen::Vector3d(a, 0.0, 0.0));
}

static double num_or(const json::Value & v, const std::string & key, double dflt)
{
  return v.has(key) ? v[key].number() : dflt;
}

static Eigen::Vector3d vec3(const json::Value & v)
{
  if (v.size() != 3)
    throw std::runtime_error("expected a 3-vector");
  return Eigen::Vector3d(v[0].number(), v[1].number(), v[2].number());
}

// One Pinocchio joint per D-H joint, as in "How the reference models were built". `hand` gets
// the hand frame's placement on the last joint, `links` each link frame's placement on its joint
// (the D-H post transform: the identity in the modified convention).
static Model build_model(const json::Value & desc, SE3 & hand, std::vector<SE3> & links)
{
  Model model;
  const std::string convention = desc.has("convention") ? desc["convention"].string() : "standard";
  if (convention != "standard" && convention != "modified")
    throw std::runtime_error("unknown convention " + convention);
  const bool modified = convention == "modified";
  const json::Value & joints = desc["joints"];
  const std::size_t n = joints.size();

  model.gravity.linear(vec3(desc["gravity"]));
  model.gravity.angular().setZero();

  std::vector<double> armature(n, 0.0);
  SE3 post_prev = SE3::Identity();
  pinocchio::JointIndex parent = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const json::Value & j = joints[i];
    const std::string type = j["type"].string();
    const bool revolute = type == "revolute";
    if (!revolute && type != "prismatic")
      throw std::runtime_error("unknown joint type " + type);
    const double theta = j["theta"].number(), d = j["d"].number();
    const double a = j["a"].number(), alpha = j["alpha"].number();
    if (num_or(j, "spring_stiffness", 0.0) != 0.0)
      throw std::runtime_error("joint springs are not modelled by Pinocchio");

    SE3 pre, post;
    if (modified)
    {
      pre = rotx(alpha) * transx(a) * rotz(theta) * transz(d);
      post = SE3::Identity();
    }
    else if (revolute)
    {
      pre = rotz(theta);
      post = transz(d) * transx(a) * rotx(alpha);
    }
    else
    {
      pre = rotz(theta) * transz(d);
      post = transx(a) * rotx(alpha);
    }

    const std::string name = "joint" + std::to_string(i + 1);
    pinocchio::JointIndex jid =
      revolute ? model.addJoint(parent, pinocchio::JointModelRZ(), post_prev * pre, name)
               : model.addJoint(parent, pinocchio::JointModelPZ(), post_prev * pre, name);

    const json::Value & in = j["inertia"]; // [Ixx, Iyy, Izz, Ixy, Ixz, Iyz] about the CoM, frame i
    Eigen::Matrix3d I;
    I << in[0].number(), in[3].number(), in[4].number(), //
      in[3].number(), in[1].number(), in[5].number(),     //
      in[4].number(), in[5].number(), in[2].number();
    const Inertia link(j["mass"].number(), vec3(j["com"]), I);
    model.appendBodyToJoint(jid, post.act(link), SE3::Identity());

    armature[i] = num_or(j, "actuator_inertia", 0.0);
    links.push_back(post);
    post_prev = post;
    parent = jid;
  }
  for (std::size_t i = 0; i < n; ++i)
    model.armature[static_cast<Eigen::Index>(i)] = armature[i];
  hand = post_prev;
  return model;
}

// The model Pinocchio's URDF loader built, as tests/data/urdf/make.py records it
// ("pinocchio_model": per joint its parent, joint type, placement and merged body). Pinocchio's
// URDF parser is a compiled library (urdfdom), which this header-only build does not link.
static Model build_model_from_pinocchio(const json::Value & record)
{
  Model model;
  model.gravity.linear(vec3(record["gravity"]));
  model.gravity.angular().setZero();
  const json::Value & joints = record["joints"];
  for (std::size_t i = 0; i < joints.size(); ++i)
  {
    const json::Value & j = joints[i];
    Eigen::Matrix3d R, I;
    for (Eigen::Index r = 0; r < 3; ++r)
      for (Eigen::Index c = 0; c < 3; ++c)
      {
        R(r, c) = j["rotation"][static_cast<std::size_t>(r)][static_cast<std::size_t>(c)].number();
        I(r, c) = j["inertia"][static_cast<std::size_t>(r)][static_cast<std::size_t>(c)].number();
      }
    const SE3 placement(R, vec3(j["translation"]));
    const auto parent = static_cast<pinocchio::JointIndex>(j["parent"].number());
    const std::string type = j["type"].string(), name = j["name"].string();
    pinocchio::JointIndex jid;
    if (type == "JointModelFreeFlyer")
      jid = model.addJoint(parent, pinocchio::JointModelFreeFlyer(), placement, name);
    else if (type == "JointModelRX")
      jid = model.addJoint(parent, pinocchio::JointModelRX(), placement, name);
    else if (type == "JointModelRY")
      jid = model.addJoint(parent, pinocchio::JointModelRY(), placement, name);
    else if (type == "JointModelRZ")
      jid = model.addJoint(parent, pinocchio::JointModelRZ(), placement, name);
    else if (type == "JointModelPX")
      jid = model.addJoint(parent, pinocchio::JointModelPX(), placement, name);
    else if (type == "JointModelPY")
      jid = model.addJoint(parent, pinocchio::JointModelPY(), placement, name);
    else if (type == "JointModelPZ")
      jid = model.addJoint(parent, pinocchio::JointModelPZ(), placement, name);
    else if (type == "JointModelRevoluteUnaligned")
      jid = model.addJoint(parent, pinocchio::JointModelRevoluteUnaligned(vec3(j["axis"])), placement, name);
    else if (type == "JointModelPrismaticUnaligned")
      jid = model.addJoint(parent, pinocchio::JointModelPrismaticUnaligned(vec3(j["axis"])), placement, name);
    else
      throw std::runtime_error("unknown Pinocchio joint type " + type);
    model.appendBodyToJoint(jid, Inertia(j["mass"].number(), vec3(j["lever"]), I), SE3::Identity());
  }
  return model;
}

// The hand frame, an operational frame on the last joint.
static pinocchio::FrameIndex add_hand_frame(Model & model, const SE3 & placement)
{
  const auto last = static_cast<pinocchio::JointIndex>(model.njoints - 1);
  return model.addFrame(pinocchio::Frame("hand", last, placement, pinocchio::OP_FRAME));
}

// ---------------------------------------------------------------------------------------------
// Vectors and matrices of the reference data
// ---------------------------------------------------------------------------------------------

static Eigen::VectorXd vecn(const json::Value & v)
{
  Eigen::VectorXd out(static_cast<Eigen::Index>(v.size()));
  for (std::size_t i = 0; i < v.size(); ++i)
    out[static_cast<Eigen::Index>(i)] = v[i].number();
  return out;
}

static Eigen::MatrixXd matn(const json::Value & v)
{
  const std::size_t rows = v.size(), cols = v[0].size();
  Eigen::MatrixXd out(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < cols; ++c)
      out(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = v[r][c].number();
  return out;
}
