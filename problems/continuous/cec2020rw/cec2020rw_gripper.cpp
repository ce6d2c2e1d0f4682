// The CEC 2020 real-world suite's RC24, the robot gripper, as the organisers' cec20_func.m computes
// it when GNU Octave runs it (the reference values of tests/data/cec2020rw/reference.tsv).
//
// f is the range of the gripping force over the fingers' displacement z in [0, Zmax]: the code finds
// its minimum and maximum with fminbnd (Brent's golden-section search with parabolic steps, tolerance
// 1e-4, at most 500 steps), so f is that search's result, a local optimum, not the true range. Where
// the mechanism cannot close, an acos argument leaves [-1, 1] and the force is complex; the search
// then goes on in complex numbers, and f (or a constraint) that ends complex is 1e4 (the code's rule).
// pride follows the search step by step with Octave's semantics, which decide where it goes:
// - a complex value whose imaginary part is 0 is a real one (Octave narrows it);
// - comparisons of real numbers are the usual ones; with a complex operand, Octave orders by modulus,
//   then by argument (-pi counted as pi). MATLAB compares real parts only, so MATLAB's search (what
//   the entrants ran) can take other steps at points where the force is complex somewhere;
// - acos of a real number above 1 is conj(std::acos), Octave's convention (0 + 1.317i for acos(2));
// - real x.^2 is std::pow(x, 2.0) and complex z.^2 is std::pow(z, 2), the integer power.
// Octave's fminbnd is restated from its documented algorithm (Brent 1973, as in Forsythe, Malcolm and
// Moler 1977) and checked against Octave's values, not copied.
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "cec2020rw_detail.hpp"

namespace pride::continuous::cec2020rw::detail {
namespace {

using Complex = std::complex<double>;

/// A scalar as Octave holds it: real when its imaginary part is 0.
struct Value {
    Complex z;
    Value(double r = 0.0) : z(r, 0.0) {}  // NOLINT: numbers mix with values as in the code
    explicit Value(Complex c) : z(c.imag() == 0.0 ? Complex(c.real(), 0.0) : c) {}
    bool real() const noexcept { return z.imag() == 0.0; }
    double re() const noexcept { return z.real(); }
};

Value operator+(Value a, Value b) {
    return a.real() && b.real() ? Value(a.re() + b.re()) : Value(a.z + b.z);
}
Value operator-(Value a, Value b) {
    return a.real() && b.real() ? Value(a.re() - b.re()) : Value(a.z - b.z);
}
Value operator-(Value a) {
    return a.real() ? Value(-a.re()) : Value(-a.z);
}
Value operator*(Value a, Value b) {
    if (a.real() && b.real()) return Value(a.re() * b.re());
    if (a.real()) return Value(Complex(a.re() * b.z.real(), a.re() * b.z.imag()));
    if (b.real()) return Value(Complex(a.z.real() * b.re(), a.z.imag() * b.re()));
    return Value(a.z * b.z);
}
Value operator/(Value a, Value b) {
    if (a.real() && b.real()) return Value(a.re() / b.re());
    if (b.real()) return Value(Complex(a.z.real() / b.re(), a.z.imag() / b.re()));
    return Value(Complex(a.z) / b.z);
}

double modulus(Value a) {
    return a.real() ? std::abs(a.re()) : std::abs(a.z);
}

/// Octave's argument for ordering complex numbers: -pi counts as pi.
double argument(Value a) {
    if (a.real()) return a.re() < 0.0 ? std::numbers::pi : 0.0;
    const double t = std::arg(a.z);
    return t == -std::numbers::pi ? std::numbers::pi : t;
}

bool operator<(Value a, Value b) {
    if (a.real() && b.real()) return a.re() < b.re();
    const double ma = modulus(a), mb = modulus(b);
    return ma < mb || (ma == mb && argument(a) < argument(b));
}
bool operator>(Value a, Value b) {
    return b < a;
}
bool operator<=(Value a, Value b) {
    if (a.real() && b.real()) return a.re() <= b.re();
    const double ma = modulus(a), mb = modulus(b);
    return ma < mb || (ma == mb && argument(a) <= argument(b));
}
bool operator>=(Value a, Value b) {
    return b <= a;
}
bool operator==(Value a, Value b) {
    return a.z == b.z;
}

Value sq(Value a) {
    return a.real() ? Value(std::pow(a.re(), 2.0)) : Value(std::pow(a.z, 2));
}
Value root(Value a) {
    if (a.real()) return a.re() >= 0.0 ? Value(std::sqrt(a.re())) : Value(Complex(0.0, std::sqrt(-a.re())));
    return Value(std::sqrt(a.z));
}
Value arccos(Value a) {
    if (!a.real()) return Value(std::acos(a.z));
    if (std::abs(a.re()) <= 1.0) return Value(std::acos(a.re()));
    const Complex y = std::acos(Complex(a.re(), 0.0));
    return Value(a.re() > 1.0 ? std::conj(y) : y);
}
Value arctan(Value a) {
    return a.real() ? Value(std::atan(a.re())) : Value(std::atan(a.z));
}
Value sine(Value a) {
    return a.real() ? Value(std::sin(a.re())) : Value(std::sin(a.z));
}
Value cosine(Value a) {
    return a.real() ? Value(std::cos(a.re())) : Value(std::cos(a.z));
}
Value sign(Value a) {
    if (!a.real()) return Value(a.z / std::abs(a.z));
    return Value(a.re() > 0.0 ? 1.0 : a.re() < 0.0 ? -1.0 : 0.0);
}
Value smaller(Value a, Value b) {  // Octave's min of two scalars (NaN-free here)
    return b < a ? b : a;
}

constexpr double kZmax = 99.9999;

/// The code's gripping force at displacement z (OBJ11's fhd with n = 1; n = 2 negates it).
struct Force {
    double a, b, c, e, l;
    Value operator()(Value z) const {
        const double P = 100;
        const Value lz = Value(l) - z;
        const Value r = root(sq(lz) + sq(e));
        const Value alpha = arccos((((sq(a) + sq(lz)) + sq(e)) - sq(b)) / (Value(2.0 * a) * r));
        const Value beta = arccos((((sq(b) + sq(lz)) + sq(e)) - sq(a)) / (Value(2.0 * b) * r));
        return Value(P * b) * sine(alpha + beta) / (Value(2.0 * c) * cosine(alpha + arctan(Value(e) / lz)));
    }
};

/// The minimum Octave's fminbnd(fun, a, b) returns (TolX 1e-4, MaxIter and MaxFunEvals 500).
template <class F>
Value fminbnd(const F& fun, Value a, Value b) {
    const double tolx = 1e-4, sqrteps = std::numeric_limits<double>::epsilon();
    const int maxiter = 500, maxfev = 500;
    const double golden = 0.5 * (3.0 - std::sqrt(5.0));
    Value v = a + Value(golden) * (b - a);
    Value w = v, x = v, e = 0.0, d = 0.0;
    Value fval = fun(x);
    Value fv = fval, fw = fval;
    int niter = 0, nfev = 1;
    while (niter < maxiter && nfev < maxfev) {
        const Value xm = Value(0.5) * (a + b);
        const Value tol = Value(2.0 * sqrteps * modulus(x) + tolx / 3.0);
        if (Value(modulus(x - xm)) <= Value(2.0) * tol - Value(0.5) * (b - a)) break;
        bool golden_step = true;
        if (Value(modulus(e)) > tol) {
            golden_step = false;
            Value r = (x - w) * (fval - fv);
            Value q = (x - v) * (fval - fw);
            Value p = (x - v) * q - (x - w) * r;
            q = Value(2.0) * (q - r);
            p = p * -sign(q);
            q = Value(modulus(q));
            r = e;
            e = d;
            if (Value(modulus(p)) < Value(modulus(Value(0.5) * q * r)) && p > q * (a - x) && p < q * (b - x)) {
                d = p / q;
                const Value u = x + d;
                if (smaller(u - a, b - u) < Value(2.0) * tol) d = tol * (sign(xm - x) + Value(xm == x ? 1.0 : 0.0));
            } else {
                golden_step = true;
            }
        }
        if (golden_step) {
            e = x >= xm ? a - x : b - x;
            d = Value(golden) * e;
        }
        const Value u = x + Value(std::max(modulus(d), modulus(tol))) * (sign(d) + Value(d == Value(0.0) ? 1.0 : 0.0));
        const Value fu = fun(u);
        ++niter;
        ++nfev;
        if (fu < fval) {
            if (u < x)
                b = x;
            else
                a = x;
            v = w, fv = fw;
            w = x, fw = fval;
            x = u, fval = fu;
        } else {
            if (u < x)
                a = u;
            else
                b = u;
            if (fu <= fw || w == x) {
                v = w, fv = fw;
                w = u, fw = fu;
            } else if (fu <= fv || v == x || v == w) {
                v = u, fv = fu;
            }
        }
    }
    return fval;
}

/// The code's rule: a complex value is 1e4.
double real_or_penalty(Value v) {
    return v.real() ? v.re() : 1e4;
}

}  // namespace

// ---- RC24: robot gripper
double rc24(const double* x, double* c) noexcept {
    const double a = x[0], b = x[1], cc = x[2], e = x[3], ff = x[4], l = x[5], delta = x[6];
    const double Ymin = 50, Ymax = 100, YG = 150;
    const Force force{a, b, cc, e, l};
    const Value lowest = fminbnd(force, 0.0, kZmax);
    const Value highest = fminbnd([&force](Value z) { return -force(z); }, 0.0, kZmax);
    const double f = real_or_penalty(-highest - lowest);
    const auto beta = [&](double lz) {
        return arccos((((sq(b) + sq(lz)) + sq(e)) - sq(a)) / (Value(2.0 * b) * root(sq(lz) + sq(e)))) -
               arctan(Value(e / lz));
    };
    const Value beta_0 = beta(l), beta_m = beta(l - kZmax);
    const Value Yxmin = Value(2.0) * (Value(e + ff) + Value(cc) * sine(beta_m + delta));
    const Value Yxmax = Value(2.0) * (Value(e + ff) + Value(cc) * sine(beta_0 + delta));
    c[0] = real_or_penalty(Yxmin - Ymin);
    c[1] = real_or_penalty(-Yxmin);
    c[2] = real_or_penalty(Value(Ymax) - Yxmax);
    c[3] = real_or_penalty(Yxmax - YG);
    c[4] = (pw(l, 2) + pw(e, 2)) - pw(a + b, 2);
    c[5] = (pw(b, 2) - pw(a - e, 2)) - pw(l - kZmax, 2);
    c[6] = kZmax - l;
    return f;
}

}  // namespace pride::continuous::cec2020rw::detail
