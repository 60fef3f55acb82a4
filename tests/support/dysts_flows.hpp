#pragma once
// Chaotic flows of the dysts database (Gilpin 2021; tests/data/dysts/README.md): their
// parameters, initial conditions and characteristic periods are read from
// tests/data/dysts/flows.tsv (copied from dysts's chaotic_attractors.json); the right-hand
// sides are written here from the equations in dysts's flows.py, each under its dysts name.
// Used by tests/analysis/test_dysts.cpp and bench/bench_dysts.cpp.

#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace pneumachaos::testing::dysts {

using State = std::vector<double>;
using Rhs = std::function<void(const State&, State&, double)>;
using Params = std::map<std::string, double>;

struct System {
  std::string name;
  Params parameters;
  State initial;
  double dt = 0.0;      ///< dysts's integration step (not used: we integrate adaptively)
  double period = 0.0;  ///< dysts's characteristic period (time units)
  double lambda_dysts = 0.0;  ///< dysts's maximum_lyapunov_estimated (1 / time unit)
};

inline double param(const Params& p, const char* key) {
  const auto it = p.find(key);
  if (it == p.end()) throw std::runtime_error(std::string("dysts: missing parameter ") + key);
  return it->second;
}

// Each flow: x, y, z (, w) = s[0..3]; the equations as in dysts's flows.py.
inline Rhs lorenz_like(const std::string& n, const Params& p) {
  const auto P = [&](const char* k) { return param(p, k); };
  if (n == "Lorenz") {
    const double b = P("beta"), r = P("rho"), s = P("sigma");
    return [=](const State& x, State& d, double) {
      d = {s * (x[1] - x[0]), r * x[0] - x[0] * x[2] - x[1], x[0] * x[1] - b * x[2]};
    };
  }
  if (n == "Chen") {
    const double a = P("a"), b = P("b"), c = P("c");
    return [=](const State& x, State& d, double) {
      d = {a * (x[1] - x[0]), (c - a) * x[0] - x[0] * x[2] + c * x[1], x[0] * x[1] - b * x[2]};
    };
  }
  if (n == "LuChen") {
    const double a = P("a"), b = P("b"), c = P("c");
    return [=](const State& x, State& d, double) {
      d = {a * (x[1] - x[0]), -x[0] * x[2] + c * x[1], x[0] * x[1] - b * x[2]};
    };
  }
  if (n == "QiChen") {
    const double a = P("a"), b = P("b"), c = P("c");
    return [=](const State& x, State& d, double) {
      d = {a * (x[1] - x[0]) + x[1] * x[2], c * x[0] + x[1] - x[0] * x[2],
           x[0] * x[1] - b * x[2]};
    };
  }
  if (n == "DequanLi" || n == "PanXuZhou" || n == "Tsucs2") {
    const double a = P("a"), c = P("c"), dd = P("d"), e = P("eps"), f = P("f"), k = P("k");
    return [=](const State& x, State& d, double) {
      d = {a * (x[1] - x[0]) + dd * x[0] * x[2], k * x[0] + f * x[1] - x[0] * x[2],
           c * x[2] + x[0] * x[1] - e * x[0] * x[0]};
    };
  }
  if (n == "YuWang") {
    const double a = P("a"), b = P("b"), c = P("c"), dd = P("d");
    return [=](const State& x, State& d, double) {
      d = {a * (x[1] - x[0]), b * x[0] - c * x[0] * x[2], std::exp(x[0] * x[1]) - dd * x[2]};
    };
  }
  return nullptr;
}

// Four-dimensional (hyperchaotic or not) extensions of the Lorenz family.
inline Rhs four_dimensional(const std::string& n, const Params& p) {
  const auto P = [&](const char* k) { return param(p, k); };
  if (n == "HyperLorenz") {
    const double a = P("a"), b = P("b"), c = P("c"), dd = P("d");
    return [=](const State& x, State& d, double) {
      d = {a * (x[1] - x[0]) + x[3], -x[0] * x[2] + c * x[0] - x[1], -b * x[2] + x[0] * x[1],
           dd * x[3] - x[0] * x[2]};
    };
  }
  if (n == "LorenzStenflo") {
    const double a = P("a"), b = P("b"), c = P("c"), dd = P("d");
    return [=](const State& x, State& d, double) {
      d = {a * (x[1] - x[0]) + dd * x[3], c * x[0] - x[0] * x[2] - x[1], x[0] * x[1] - b * x[2],
           -x[0] - a * x[3]};
    };
  }
  if (n == "Qi") {
    const double a = P("a"), b = P("b"), c = P("c"), dd = P("d");
    return [=](const State& x, State& d, double) {
      d = {a * (x[1] - x[0]) + x[1] * x[2] * x[3], b * (x[0] + x[1]) - x[0] * x[2] * x[3],
           -c * x[2] + x[0] * x[1] * x[3], -dd * x[3] + x[0] * x[1] * x[2]};
    };
  }
  return nullptr;
}

inline Rhs quadratic_3d(const std::string& n, const Params& p) {
  const auto P = [&](const char* k) { return param(p, k); };
  if (n == "ChenLee") {
    const double a = P("a"), b = P("b"), c = P("c");
    return [=](const State& x, State& d, double) {
      d = {a * x[0] - x[1] * x[2], b * x[1] + x[0] * x[2], c * x[2] + x[0] * x[1] / 3.0};
    };
  }
  if (n == "LuChenCheng") {
    const double a = P("a"), b = P("b"), c = P("c");
    return [=](const State& x, State& d, double) {
      d = {-(a * b) / (a + b) * x[0] - x[1] * x[2] + c, a * x[1] + x[0] * x[2],
           b * x[2] + x[0] * x[1]};
    };
  }
  if (n == "BurkeShaw") {
    const double e = P("e"), m = P("n");
    return [=](const State& x, State& d, double) {
      d = {-m * (x[0] + x[1]), x[1] - m * x[0] * x[2], m * x[0] * x[1] + e};
    };
  }
  if (n == "Dadras") {
    const double c = P("c"), e = P("e"), o = P("o"), pp = P("p"), r = P("r");
    return [=](const State& x, State& d, double) {
      d = {x[1] - pp * x[0] + o * x[1] * x[2], r * x[1] - x[0] * x[2] + x[2],
           c * x[0] * x[1] - e * x[2]};
    };
  }
  if (n == "Finance") {
    const double a = P("a"), b = P("b"), c = P("c");
    return [=](const State& x, State& d, double) {
      d = {(1.0 / b - a) * x[0] + x[2] + x[0] * x[1], -b * x[1] - x[0] * x[0], -x[0] - c * x[2]};
    };
  }
  if (n == "Hadley" || n == "Lorenz84") {  // the same equations in dysts
    const double a = P("a"), b = P("b"), f = P("f"), g = P("g");
    return [=](const State& x, State& d, double) {
      d = {-x[1] * x[1] - x[2] * x[2] - a * x[0] + a * f, x[0] * x[1] - b * x[0] * x[2] - x[1] + g,
           b * x[0] * x[1] + x[0] * x[2] - x[2]};
    };
  }
  if (n == "Halvorsen") {
    const double a = P("a"), b = P("b");
    return [=](const State& x, State& d, double) {
      d = {-a * x[0] - b * (x[1] + x[2]) - x[1] * x[1], -a * x[1] - b * (x[2] + x[0]) - x[2] * x[2],
           -a * x[2] - b * (x[0] + x[1]) - x[0] * x[0]};
    };
  }
  return nullptr;
}

// More three-dimensional flows with quadratic terms.
inline Rhs quadratic_3d_more(const std::string& n, const Params& p) {
  const auto P = [&](const char* k) { return param(p, k); };
  if (n == "NewtonLiepnik") {
    const double a = P("a"), b = P("b");
    return [=](const State& x, State& d, double) {
      d = {-a * x[0] + x[1] + 10.0 * x[1] * x[2], -x[0] - 0.4 * x[1] + 5.0 * x[0] * x[2],
           b * x[2] - 5.0 * x[0] * x[1]};
    };
  }
  if (n == "RikitakeDynamo") {
    const double a = P("a"), mu = P("mu");
    return [=](const State& x, State& d, double) {
      d = {-mu * x[0] + x[1] * x[2], -mu * x[1] - a * x[0] + x[0] * x[2], 1.0 - x[0] * x[1]};
    };
  }
  if (n == "Rossler") {
    const double a = P("a"), b = P("b"), c = P("c");
    return [=](const State& x, State& d, double) {
      d = {-x[1] - x[2], x[0] + a * x[1], b + x[2] * x[0] - c * x[2]};
    };
  }
  if (n == "Rucklidge") {
    const double a = P("a"), b = P("b");
    return [=](const State& x, State& d, double) {
      d = {-a * x[0] + b * x[1] - x[1] * x[2], x[0], -x[2] + x[1] * x[1]};
    };
  }
  return nullptr;
}

// And more: Sakarya's family, jerk-like quadratics, the laser model.
inline Rhs quadratic_3d_last(const std::string& n, const Params& p) {
  const auto P = [&](const char* k) { return param(p, k); };
  if (n == "Sakarya" || n == "LiuChen") {
    const double a = P("a"), b = P("b"), c = P("c"), h = P("h"), pp = P("p"), q = P("q"),
                 r = P("r"), s = P("s");
    return [=](const State& x, State& d, double) {
      d = {a * x[0] + h * x[1] + s * x[1] * x[2], -b * x[1] - pp * x[0] + q * x[0] * x[2],
           c * x[2] - r * x[0] * x[1]};
    };
  }
  if (n == "ShimizuMorioka") {
    const double a = P("a"), b = P("b");
    return [=](const State& x, State& d, double) {
      d = {x[1], x[0] - a * x[1] - x[0] * x[2], -b * x[2] + x[0] * x[0]};
    };
  }
  if (n == "WangSun") {
    const double a = P("a"), b = P("b"), dd = P("d"), e = P("e"), f = P("f"), q = P("q");
    return [=](const State& x, State& d, double) {
      d = {a * x[0] + q * x[1] * x[2], b * x[0] + dd * x[1] - x[0] * x[2],
           e * x[2] + f * x[0] * x[1]};
    };
  }
  if (n == "ZhouChen") {
    const double a = P("a"), b = P("b"), c = P("c"), dd = P("d"), e = P("e");
    return [=](const State& x, State& d, double) {
      d = {a * x[0] + b * x[1] + x[1] * x[2], c * x[1] - x[0] * x[2] + dd * x[1] * x[2],
           e * x[2] - x[0] * x[1]};
    };
  }
  if (n == "PehlivanWei") {
    return [](const State& x, State& d, double) {
      d = {x[1] - x[1] * x[2], x[1] + x[1] * x[2] - 2.0 * x[0], 2.0 - x[0] * x[1] - x[1] * x[1]};
    };
  }
  if (n == "Laser") {
    const double a = P("a"), b = P("b"), c = P("c"), dd = P("d"), h = P("h"), k = P("k");
    return [=](const State& x, State& d, double) {
      const double z2 = x[2] * x[2];
      d = {a * (x[1] - x[0]) + b * x[1] * z2, c * x[0] + dd * x[0] * z2, h * x[2] + k * x[0] * x[0]};
    };
  }
  return nullptr;
}

// Jerk (third-order) systems and the thermostatted oscillator.
inline Rhs jerk(const std::string& n, const Params& p) {
  const auto P = [&](const char* k) { return param(p, k); };
  if (n == "Arneodo" || n == "Coullet") {
    const double a = P("a"), b = P("b"), c = P("c"), dd = P("d");
    return [=](const State& x, State& d, double) {
      d = {x[1], x[2], -a * x[0] - b * x[1] - c * x[2] + dd * x[0] * x[0] * x[0]};
    };
  }
  if (n == "GenesioTesi") {
    const double a = P("a"), b = P("b"), c = P("c");
    return [=](const State& x, State& d, double) {
      d = {x[1], x[2], -c * x[0] - b * x[1] - a * x[2] + x[0] * x[0]};
    };
  }
  if (n == "SprottJerk") {
    const double mu = P("mu");
    return [=](const State& x, State& d, double) {
      d = {x[1], x[2], -x[0] + x[1] * x[1] - mu * x[2]};
    };
  }
  if (n == "MooreSpiegel") {
    const double a = P("a"), b = P("b"), eps = P("eps");
    return [=](const State& x, State& d, double) {
      d = {x[1], a * x[2], -x[2] + eps * x[1] - x[1] * x[0] * x[0] - b * x[0]};
    };
  }
  if (n == "NoseHoover") {
    const double a = P("a");
    return [=](const State& x, State& d, double) {
      d = {x[1], -x[0] + x[1] * x[2], a - x[1] * x[1]};
    };
  }
  return nullptr;
}

// The rest: cubic, trigonometric, Hamiltonian and cyclic.
inline Rhs other(const std::string& n, const Params& p) {
  const auto P = [&](const char* k) { return param(p, k); };
  if (n == "Aizawa") {
    const double a = P("a"), b = P("b"), c = P("c"), dd = P("d"), e = P("e"), f = P("f");
    return [=](const State& x, State& d, double) {
      const double r2 = x[0] * x[0] + x[1] * x[1];
      d = {x[0] * x[2] - b * x[0] - dd * x[1], dd * x[0] + x[1] * x[2] - b * x[1],
           c + a * x[2] - x[2] * x[2] * x[2] / 3.0 - r2 - e * x[2] * r2 +
               f * x[2] * x[0] * x[0] * x[0]};
    };
  }
  if (n == "Thomas" || n == "ThomasLabyrinth") {
    const double a = P("a"), b = P("b");
    return [=](const State& x, State& d, double) {
      d = {-a * x[0] + b * std::sin(x[1]), -a * x[1] + b * std::sin(x[2]),
           -a * x[2] + b * std::sin(x[0])};
    };
  }
  if (n == "RabinovichFabrikant") {
    const double a = P("a"), g = P("g");
    return [=](const State& x, State& d, double) {
      d = {x[1] * x[2] - x[1] + x[1] * x[0] * x[0] + g * x[0],
           3.0 * x[0] * x[2] + x[0] - x[0] * x[0] * x[0] + g * x[1],
           -2.0 * a * x[2] - 2.0 * x[0] * x[1] * x[2]};
    };
  }
  if (n == "HindmarshRose") {
    const double a = P("a"), b = P("b"), c = P("c"), dd = P("d"), s = P("s"), tx = P("tx"),
                 tz = P("tz");
    return [=](const State& x, State& d, double) {
      const double x2 = x[0] * x[0], x3 = x2 * x[0];
      d = {-x[0] + (x[1] - a * x3 + b * x2 + x[2]) / tx, -a * x3 - (dd - b) * x2 + x[2],
           (-s * x[0] - x[2] + c) / tz};
    };
  }
  if (n == "HenonHeiles") {  // state x, y, px, py
    const double lam = P("lam");
    return [=](const State& x, State& d, double) {
      d = {x[2], x[3], -x[0] - 2.0 * lam * x[0] * x[1],
           -x[1] - lam * x[0] * x[0] + lam * x[1] * x[1]};
    };
  }
  if (n == "Lorenz96") {  // dysts's class: cyclic, N = the initial condition's length
    const double f = P("f");
    return [=](const State& x, State& d, double) {
      const std::size_t N = x.size();
      d.resize(N);
      for (std::size_t i = 0; i < N; ++i) {
        d[i] = (x[(i + 1) % N] - x[(i + N - 2) % N]) * x[(i + N - 1) % N] - x[i] + f;
      }
    };
  }
  return nullptr;
}

// Sprott's simple flows A-S (Sprott 1994, Phys. Rev. E 50), as in dysts.
inline Rhs sprott(const std::string& n, const Params& p) {
  const auto P = [&](const char* k) { return param(p, k); };
  using V = void (*)(const State&, State&, double);
  static const std::map<std::string, V> fixed{
      {"SprottA", [](const State& x, State& d, double) {
         d = {x[1], -x[0] + x[1] * x[2], 1.0 - x[1] * x[1]}; }},
      {"SprottB", [](const State& x, State& d, double) {
         d = {x[1] * x[2], x[0] - x[1], 1.0 - x[0] * x[1]}; }},
      {"SprottC", [](const State& x, State& d, double) {
         d = {x[1] * x[2], x[0] - x[1], 1.0 - x[0] * x[0]}; }},
      {"SprottD", [](const State& x, State& d, double) {
         d = {-x[1], x[0] + x[2], x[0] * x[2] + 3.0 * x[1] * x[1]}; }},
      {"SprottE", [](const State& x, State& d, double) {
         d = {x[1] * x[2], x[0] * x[0] - x[1], 1.0 - 4.0 * x[0]}; }},
      {"SprottJ", [](const State& x, State& d, double) {
         d = {2.0 * x[2], -2.0 * x[1] + x[2], -x[0] + x[1] + x[1] * x[1]}; }},
      {"SprottN", [](const State& x, State& d, double) {
         d = {-2.0 * x[1], x[0] + x[2] * x[2], 1.0 + x[1] - 2.0 * x[2]}; }},
      {"SprottS", [](const State& x, State& d, double) {
         d = {-x[0] - 4.0 * x[1], x[0] + x[2] * x[2], 1.0 + x[0]}; }}};
  if (const auto it = fixed.find(n); it != fixed.end()) return it->second;
  if (n == "SprottF" || n == "SprottG" || n == "SprottH" || n == "SprottI" || n == "SprottK" ||
      n == "SprottM" || n == "SprottO" || n == "SprottP") {
    const double a = P("a");
    const char c = n.back();
    return [=](const State& x, State& d, double) {
      switch (c) {
        case 'F': d = {x[1] + x[2], -x[0] + a * x[1], x[0] * x[0] - x[2]}; break;
        case 'G': d = {a * x[0] + x[2], x[0] * x[2] - x[1], -x[0] + x[1]}; break;
        case 'H': d = {-x[1] + x[2] * x[2], x[0] + a * x[1], x[0] - x[2]}; break;
        case 'I': d = {-a * x[1], x[0] + x[2], x[0] + x[1] * x[1] - x[2]}; break;
        case 'K': d = {x[0] * x[1] - x[2], x[0] - x[1], x[0] + a * x[2]}; break;
        case 'M': d = {-x[2], -x[0] * x[0] - x[1], a + a * x[0] + x[1]}; break;
        case 'O': d = {x[1], x[0] - x[2], x[0] + x[0] * x[2] + a * x[1]}; break;
        default: d = {a * x[1] + x[2], -x[0] + x[1] * x[1], x[0] + x[1]}; break;  // P
      }
    };
  }
  if (n == "SprottL" || n == "SprottQ" || n == "SprottR") {
    const double a = P("a"), b = P("b");
    const char c = n.back();
    return [=](const State& x, State& d, double) {
      if (c == 'L') d = {x[1] + b * x[2], a * x[0] * x[0] - x[1], 1.0 - x[0]};
      if (c == 'Q') d = {-x[2], x[0] - x[1], a * x[0] + x[1] * x[1] + b * x[2]};
      if (c == 'R') d = {a - x[1], b + x[2], x[0] * x[1] - x[2]};
    };
  }
  return nullptr;
}

inline Rhs vector_field(const System& s) {
  for (const auto make : {lorenz_like, four_dimensional, quadratic_3d, quadratic_3d_more,
                          quadratic_3d_last, jerk, other, sprott}) {
    if (Rhs r = make(s.name, s.parameters)) return r;
  }
  throw std::runtime_error("dysts: no right-hand side for " + s.name);
}

inline std::vector<double> numbers(const std::string& text, char sep) {
  std::vector<double> v;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, sep);) v.push_back(std::stod(item));
  return v;
}

/// Reads flows.tsv (tests/data/dysts/README.md); throws naming the line on a malformed one.
inline std::vector<System> load_systems(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("dysts: cannot open " + path);
  std::vector<System> out;
  std::size_t line_no = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    std::stringstream ls(line);
    for (std::string cell; std::getline(ls, cell, '\t');) f.push_back(cell);
    if (f.size() != 6) {
      throw std::runtime_error(path + ":" + std::to_string(line_no) + ": 6 fields expected");
    }
    System s{f[0], {}, numbers(f[2], ','), std::stod(f[3]), std::stod(f[4]), std::stod(f[5])};
    if (f[1] != "-") {
      std::stringstream ps(f[1]);
      for (std::string kv; std::getline(ps, kv, ';');) {
        const auto eq = kv.find('=');
        s.parameters[kv.substr(0, eq)] = std::stod(kv.substr(eq + 1));
      }
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace pneumachaos::testing::dysts
