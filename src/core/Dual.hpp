// Forward-mode automatic differentiation: a value with its gradient with respect to N seeded
// variables, carried through +, -, *, /, sqrt and abs by the chain rule. Comparisons look at
// the value only, so a branch taken on the value is differentiated as taken (the derivative
// of the branch's formula; at a kink, one side's). Used where a derivative must be exact and a
// hand linearisation would be long: the mortar gap's dependence on the nodes' positions.
#pragma once
#include <array>
#include <cmath>

namespace choc {

template <int N>
struct Dual {
  double v = 0;
  std::array<double, N> g{};

  Dual() = default;
  Dual(double value) : v(value) {}  // a constant (implicit: mixes with double in formulas)
  // Variable k of the N seeded ones, at value x.
  static Dual variable(double x, int k) {
    Dual d(x);
    d.g[size_t(k)] = 1.0;
    return d;
  }

  Dual& operator+=(const Dual& b) {
    v += b.v;
    for (int k = 0; k < N; ++k) g[k] += b.g[k];
    return *this;
  }
  Dual& operator-=(const Dual& b) {
    v -= b.v;
    for (int k = 0; k < N; ++k) g[k] -= b.g[k];
    return *this;
  }
  Dual& operator*=(const Dual& b) { return *this = *this * b; }
  Dual& operator/=(const Dual& b) { return *this = *this / b; }

  friend Dual operator+(Dual a, const Dual& b) { return a += b; }
  friend Dual operator-(Dual a, const Dual& b) { return a -= b; }
  friend Dual operator-(Dual a) {
    a.v = -a.v;
    for (int k = 0; k < N; ++k) a.g[k] = -a.g[k];
    return a;
  }
  friend Dual operator*(const Dual& a, const Dual& b) {
    Dual c(a.v * b.v);
    for (int k = 0; k < N; ++k) c.g[k] = a.g[k] * b.v + a.v * b.g[k];
    return c;
  }
  friend Dual operator/(const Dual& a, const Dual& b) {
    Dual c(a.v / b.v);
    for (int k = 0; k < N; ++k) c.g[k] = (a.g[k] - c.v * b.g[k]) / b.v;
    return c;
  }
  friend bool operator<(const Dual& a, const Dual& b) { return a.v < b.v; }
  friend bool operator>(const Dual& a, const Dual& b) { return a.v > b.v; }
  friend bool operator<=(const Dual& a, const Dual& b) { return a.v <= b.v; }
  friend bool operator>=(const Dual& a, const Dual& b) { return a.v >= b.v; }
};

template <int N>
Dual<N> sqrt(const Dual<N>& a) {
  Dual<N> c(std::sqrt(a.v));
  for (int k = 0; k < N; ++k) c.g[k] = a.g[k] / (2.0 * c.v);
  return c;
}

template <int N>
Dual<N> abs(const Dual<N>& a) {
  return a.v < 0 ? -a : a;
}

// The value of a double or of a Dual (for tests of convergence and of degeneracy).
inline double valueOf(double x) { return x; }
template <int N>
double valueOf(const Dual<N>& x) {
  return x.v;
}

}  // namespace choc
