// The basic functions, statement by statement as the official codes write them (kernel.hpp says
// where that differs from the report). Accumulation orders and the pow() calls are kept, so that
// values agree with the official code to the last bits the rotation leaves.
#include "problems/continuous/cec/kernel.hpp"

#include "problems/continuous/cec/data.hpp"

#include <array>
#include <cmath>

namespace pride::continuous::cec {

namespace {

constexpr double kInf = 1.0e99;  // the official INF: cf_cal's weight at a component's optimum
constexpr double kE = 2.7182818284590452353602874713526625;
constexpr double kPi = 3.1415926535897932384626433832795029;

/// out = M in (Data::rotation's layout for nx): out_i = ((0 + in_0 M_i0) + in_1 M_i1) + ..., the
/// official rotatefunc's order for every i, so the bits are the official code's. Small matrices by
/// rows, four rows at once (four independent sums); large ones by columns, each column one Eigen
/// vector operation over all i.
void rotate(const double* in, double* out, int nx, const double* m) {
    if (static_cast<std::size_t>(nx) >= kRotateByColumns) {
        Eigen::Map<Eigen::VectorXd> o(out, nx);
        o.setZero();
        for (int j = 0; j < nx; ++j)
            o += in[j] * Eigen::Map<const Eigen::VectorXd>(m + static_cast<std::ptrdiff_t>(j) * nx, nx);
        return;
    }
    int i = 0;
    for (; i + 4 <= nx; i += 4) {
        const double* m0 = m + static_cast<std::ptrdiff_t>(i) * nx;
        const double *m1 = m0 + nx, *m2 = m1 + nx, *m3 = m2 + nx;
        double a0 = 0, a1 = 0, a2 = 0, a3 = 0;
        for (int j = 0; j < nx; ++j) {
            const double x = in[j];
            a0 = a0 + x * m0[j];
            a1 = a1 + x * m1[j];
            a2 = a2 + x * m2[j];
            a3 = a3 + x * m3[j];
        }
        out[i] = a0;
        out[i + 1] = a1;
        out[i + 2] = a2;
        out[i + 3] = a3;
    }
    for (; i < nx; ++i) {
        const double* row = m + static_cast<std::ptrdiff_t>(i) * nx;
        double a = 0;
        for (int j = 0; j < nx; ++j) a = a + in[j] * row[j];
        out[i] = a;
    }
}

}  // namespace

void Kernel::shift_rotate(const double* x, double* out, int nx, const double* os, const double* mr, double rate, bool s,
                          bool r) {
    double* y = y_.data();
    if (s) {
        if (r) {
            for (int i = 0; i < nx; ++i) y[i] = (x[i] - os[i]) * rate;
            rotate(y, out, nx, mr);
        } else {
            for (int i = 0; i < nx; ++i) out[i] = (x[i] - os[i]) * rate;
        }
    } else if (r) {
        for (int i = 0; i < nx; ++i) y[i] = x[i] * rate;
        rotate(y, out, nx, mr);
    } else {
        for (int i = 0; i < nx; ++i) out[i] = x[i] * rate;
    }
}

double Kernel::ellips(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* z = z_.data();
    shift_rotate(x, z, nx, os, mr, 1.0, s, r);
    double f = 0.0;
    for (int i = 0; i < nx; ++i) f += std::pow(10.0, 6.0 * i / (nx - 1)) * z[i] * z[i];
    return f;
}

double Kernel::bent_cigar(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* z = z_.data();
    shift_rotate(x, z, nx, os, mr, 1.0, s, r);
    double f = z[0] * z[0];
    for (int i = 1; i < nx; ++i) f += 1.0e6 * z[i] * z[i];
    return f;
}

double Kernel::discus(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* z = z_.data();
    shift_rotate(x, z, nx, os, mr, 1.0, s, r);
    double f = 1.0e6 * z[0] * z[0];
    for (int i = 1; i < nx; ++i) f += z[i] * z[i];
    return f;
}

double Kernel::sum_diff_pow(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* z = z_.data();
    shift_rotate(x, z, nx, os, mr, 1.0, s, r);
    double sum = 0.0;
    // The official abs() is the C++ double overload (the file is compiled as C++): |z_i|^(i+1).
    for (int i = 0; i < nx; ++i) sum = sum + std::pow(std::fabs(z[i]), i + 1);
    return sum;
}

double Kernel::zakharov(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* z = z_.data();
    shift_rotate(x, z, nx, os, mr, 1.0, s, r);
    double sum1 = 0.0, sum2 = 0.0;
    for (int i = 0; i < nx; ++i) {
        const double xi = z[i];
        sum1 = sum1 + std::pow(xi, 2);
        sum2 = sum2 + 0.5 * (i + 1) * xi;
    }
    return sum1 + std::pow(sum2, 2) + std::pow(sum2, 4);
}

double Kernel::levy(const double* x, int nx, const double* os, const double* mr, bool s, bool r, bool y2022) {
    double* z = z_.data();
    double* w = tmp_.data();
    shift_rotate(x, z, nx, os, mr, 1.0, s, r);
    for (int i = 0; i < nx; ++i) w[i] = y2022 ? 1.0 + (z[i] - 0.0) / 4.0 : 1.0 + (z[i] - 1.0) / 4.0;
    const double term1 = std::pow(std::sin(kPi * w[0]), 2);
    const double term3 = std::pow(w[nx - 1] - 1, 2) * (1 + std::pow(std::sin(2 * kPi * w[nx - 1]), 2));
    double sum = 0.0;
    for (int i = 0; i < nx - 1; ++i) {
        const double wi = w[i];
        sum = sum + std::pow(wi - 1, 2) * (1 + 10 * std::pow(std::sin(kPi * wi + 1), 2));
    }
    return term1 + sum + term3;
}

double Kernel::rosenbrock(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* z = z_.data();
    shift_rotate(x, z, nx, os, mr, 2.048 / 100.0, s, r);
    double f = 0.0;
    z[0] += 1.0;
    for (int i = 0; i < nx - 1; ++i) {
        z[i + 1] += 1.0;
        const double tmp1 = z[i] * z[i] - z[i + 1];
        const double tmp2 = z[i] - 1.0;
        f += 100.0 * tmp1 * tmp1 + tmp2 * tmp2;
    }
    return f;
}

double Kernel::schaffer_f7(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* z = z_.data();
    const double* y = y_.data();  // the official code reads y here (kernel.hpp)
    shift_rotate(x, z, nx, os, mr, 1.0, s, r);
    double f = 0.0;
    for (int i = 0; i < nx - 1; ++i) {
        z[i] = std::pow(y[i] * y[i] + y[i + 1] * y[i + 1], 0.5);
        const double tmp = std::sin(50.0 * std::pow(z[i], 0.2));
        const double root = std::pow(z[i], 0.5);  // the official code calls pow twice, same bits
        f += root + root * tmp * tmp;
    }
    return f * f / (nx - 1) / (nx - 1);
}

double Kernel::ackley(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* z = z_.data();
    shift_rotate(x, z, nx, os, mr, 1.0, s, r);
    double sum1 = 0.0, sum2 = 0.0;
    for (int i = 0; i < nx; ++i) {
        sum1 += z[i] * z[i];
        sum2 += std::cos(2.0 * kPi * z[i]);
    }
    sum1 = -0.2 * std::sqrt(sum1 / nx);
    sum2 /= nx;
    return kE - 20.0 * std::exp(sum1) - std::exp(sum2) + 20.0;
}

// a^j and b^j are exact in double for j <= 20, so tables give pow()'s bits; the second sum does
// not depend on x and is computed once, in the official order.
struct WeierstrassTables {
    std::array<double, 21> a_j{}, b_j{};
    double sum2 = 0.0;
    WeierstrassTables() {
        for (int j = 0; j <= 20; ++j) {
            a_j[j] = std::pow(0.5, j);
            b_j[j] = std::pow(3.0, j);
            sum2 += a_j[j] * std::cos(2.0 * kPi * b_j[j] * 0.5);
        }
    }
};

double Kernel::weierstrass(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    static const WeierstrassTables t;
    double* z = z_.data();
    shift_rotate(x, z, nx, os, mr, 0.5 / 100.0, s, r);
    double f = 0.0;
    for (int i = 0; i < nx; ++i) {
        double sum = 0.0;
        for (int j = 0; j <= 20; ++j) sum += t.a_j[j] * std::cos(2.0 * kPi * t.b_j[j] * (z[i] + 0.5));
        f += sum;
    }
    return f - nx * t.sum2;
}

double Kernel::griewank(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* z = z_.data();
    shift_rotate(x, z, nx, os, mr, 600.0 / 100.0, s, r);
    double sum = 0.0, product = 1.0;
    for (int i = 0; i < nx; ++i) {
        sum += z[i] * z[i];
        product *= std::cos(z[i] / std::sqrt(1.0 + i));
    }
    return 1.0 + sum / 4000.0 - product;
}

double Kernel::rastrigin(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* z = z_.data();
    shift_rotate(x, z, nx, os, mr, 5.12 / 100.0, s, r);
    double f = 0.0;
    for (int i = 0; i < nx; ++i) f += (z[i] * z[i] - 10.0 * std::cos(2.0 * kPi * z[i]) + 10.0);
    return f;
}

double Kernel::step_rastrigin(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    // The official code rounds y here, then sr_func overwrites y (kernel.hpp): Rastrigin's value.
    return rastrigin(x, nx, os, mr, s, r);
}

double Kernel::schwefel(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* z = z_.data();
    shift_rotate(x, z, nx, os, mr, 1000.0 / 100.0, s, r);
    double f = 0.0;
    for (int i = 0; i < nx; ++i) {
        z[i] += 4.209687462275036e+002;
        if (z[i] > 500) {
            f -= (500.0 - std::fmod(z[i], 500)) * std::sin(std::pow(500.0 - std::fmod(z[i], 500), 0.5));
            const double tmp = (z[i] - 500.0) / 100;
            f += tmp * tmp / nx;
        } else if (z[i] < -500) {
            f -= (-500.0 + std::fmod(std::fabs(z[i]), 500)) *
                 std::sin(std::pow(500.0 - std::fmod(std::fabs(z[i]), 500), 0.5));
            const double tmp = (z[i] + 500.0) / 100;
            f += tmp * tmp / nx;
        } else {
            f -= z[i] * std::sin(std::pow(std::fabs(z[i]), 0.5));
        }
    }
    return f + 4.189828872724338e+002 * nx;
}

double Kernel::katsuura(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* z = z_.data();
    double f = 1.0;
    const double tmp3 = std::pow(1.0 * nx, 1.2);
    shift_rotate(x, z, nx, os, mr, 5.0 / 100.0, s, r);
    for (int i = 0; i < nx; ++i) {
        double temp = 0.0;
        // 2^j and the division by it are exact: the scaling by 2^-j gives the same bits.
        double two_j = 1.0, inverse = 1.0;
        for (int j = 1; j <= 32; ++j) {
            two_j *= 2.0;
            inverse *= 0.5;
            const double tmp2 = two_j * z[i];
            temp += std::fabs(tmp2 - std::floor(tmp2 + 0.5)) * inverse;
        }
        f *= std::pow(1.0 + (i + 1) * temp, 10.0 / tmp3);
    }
    const double tmp1 = 10.0 / nx / nx;
    return f * tmp1 - tmp1;
}

double Kernel::bi_rastrigin(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* y = y_.data();
    double* z = z_.data();
    double* tmpx = tmp_.data();
    constexpr double mu0 = 2.5, d = 1.0;
    const double sv = 1.0 - 1.0 / (2.0 * std::pow(nx + 20.0, 0.5) - 8.2);
    const double mu1 = -std::pow((mu0 * mu0 - d) / sv, 0.5);
    // In a hybrid x points into y: the official copy runs forwards, element by element.
    if (s) {
        for (int i = 0; i < nx; ++i) y[i] = x[i] - os[i];
    } else {
        for (int i = 0; i < nx; ++i) y[i] = x[i];
    }
    for (int i = 0; i < nx; ++i) y[i] *= 10.0 / 100.0;
    for (int i = 0; i < nx; ++i) {
        tmpx[i] = 2 * y[i];
        if (os[i] < 0.0) tmpx[i] *= -1.;
    }
    for (int i = 0; i < nx; ++i) {
        z[i] = tmpx[i];
        tmpx[i] += mu0;
    }
    double tmp1 = 0.0, tmp2 = 0.0;
    for (int i = 0; i < nx; ++i) {
        double tmp = tmpx[i] - mu0;
        tmp1 += tmp * tmp;
        tmp = tmpx[i] - mu1;
        tmp2 += tmp * tmp;
    }
    tmp2 *= sv;
    tmp2 += d * nx;
    double tmp = 0.0;
    const double* c = z;
    if (r) {
        rotate(z, y, nx, mr);
        c = y;
    }
    for (int i = 0; i < nx; ++i) tmp += std::cos(2.0 * kPi * c[i]);
    double f = tmp1 < tmp2 ? tmp1 : tmp2;
    f += 10.0 * (nx - tmp);
    return f;
}

double Kernel::grie_rosen(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* z = z_.data();
    shift_rotate(x, z, nx, os, mr, 5.0 / 100.0, s, r);
    double f = 0.0;
    z[0] += 1.0;
    for (int i = 0; i < nx - 1; ++i) {
        z[i + 1] += 1.0;
        const double tmp1 = z[i] * z[i] - z[i + 1];
        const double tmp2 = z[i] - 1.0;
        const double temp = 100.0 * tmp1 * tmp1 + tmp2 * tmp2;
        f += (temp * temp) / 4000.0 - std::cos(temp) + 1.0;
    }
    const double tmp1 = z[nx - 1] * z[nx - 1] - z[0];
    const double tmp2 = z[nx - 1] - 1.0;
    const double temp = 100.0 * tmp1 * tmp1 + tmp2 * tmp2;
    f += (temp * temp) / 4000.0 - std::cos(temp) + 1.0;
    return f;
}

double Kernel::escaffer6(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* z = z_.data();
    shift_rotate(x, z, nx, os, mr, 1.0, s, r);
    double f = 0.0;
    for (int i = 0; i < nx - 1; ++i) {
        double temp1 = std::sin(std::sqrt(z[i] * z[i] + z[i + 1] * z[i + 1]));
        temp1 = temp1 * temp1;
        const double temp2 = 1.0 + 0.001 * (z[i] * z[i] + z[i + 1] * z[i + 1]);
        f += 0.5 + (temp1 - 0.5) / (temp2 * temp2);
    }
    double temp1 = std::sin(std::sqrt(z[nx - 1] * z[nx - 1] + z[0] * z[0]));
    temp1 = temp1 * temp1;
    const double temp2 = 1.0 + 0.001 * (z[nx - 1] * z[nx - 1] + z[0] * z[0]);
    f += 0.5 + (temp1 - 0.5) / (temp2 * temp2);
    return f;
}

double Kernel::happycat(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* z = z_.data();
    constexpr double alpha = 1.0 / 8.0;
    shift_rotate(x, z, nx, os, mr, 5.0 / 100.0, s, r);
    double r2 = 0.0, sum_z = 0.0;
    for (int i = 0; i < nx; ++i) {
        z[i] = z[i] - 1.0;
        r2 += z[i] * z[i];
        sum_z += z[i];
    }
    return std::pow(std::fabs(r2 - nx), 2 * alpha) + (0.5 * r2 + sum_z) / nx + 0.5;
}

double Kernel::hgbat(const double* x, int nx, const double* os, const double* mr, bool s, bool r) {
    double* z = z_.data();
    constexpr double alpha = 1.0 / 4.0;
    shift_rotate(x, z, nx, os, mr, 5.0 / 100.0, s, r);
    double r2 = 0.0, sum_z = 0.0;
    for (int i = 0; i < nx; ++i) {
        z[i] = z[i] - 1.0;
        r2 += z[i] * z[i];
        sum_z += z[i];
    }
    return std::pow(std::fabs(std::pow(r2, 2.0) - std::pow(sum_z, 2.0)), 2 * alpha) + (0.5 * r2 + sum_z) / nx + 0.5;
}

void Kernel::permute(const double* x, int nx, const double* os, const double* mr, const int* shuffle) {
    double* z = z_.data();
    double* y = y_.data();
    shift_rotate(x, z, nx, os, mr, 1.0, true, true);
    for (int i = 0; i < nx; ++i) y[i] = z[shuffle[i]];
}

double Kernel::compose(const double* x, int nx, const double* os, const double* delta, const double* bias, double* fit,
                       int components) {
    std::array<double, 12> w{};
    double w_max = 0, w_sum = 0;
    for (int i = 0; i < components; ++i) {
        fit[i] += bias[i];
        w[i] = 0;
        for (int j = 0; j < nx; ++j) w[i] += std::pow(x[j] - os[i * nx + j], 2.0);
        if (w[i] != 0)
            w[i] = std::pow(1.0 / w[i], 0.5) * std::exp(-w[i] / 2.0 / nx / std::pow(delta[i], 2.0));
        else
            w[i] = kInf;
        if (w[i] > w_max) w_max = w[i];
    }
    for (int i = 0; i < components; ++i) w_sum = w_sum + w[i];
    if (w_max == 0) {
        for (int i = 0; i < components; ++i) w[i] = 1;
        w_sum = components;
    }
    double f = 0.0;
    for (int i = 0; i < components; ++i) f = f + w[i] / w_sum * fit[i];
    return f;
}

}  // namespace pride::continuous::cec
