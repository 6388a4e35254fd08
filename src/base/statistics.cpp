#include "base/statistics.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

namespace kiln {

double RunningStats::StandardError() const { return std::sqrt(Variance() / std::max(1LL, n)); }

// Series for P(a, x) when x < a + 1, continued fraction for Q(a, x) otherwise
// (Numerical Recipes' approach, written from the definitions).
double RegularizedGammaQ(double a, double x) {
    if (x <= 0) return 1;
    double lnPrefix = -x + a * std::log(x) - std::lgamma(a);
    if (x < a + 1) {
        double sum = 1 / a, term = sum;
        for (int n = 1; n < 10000; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::abs(term) < std::abs(sum) * 1e-15) break;
        }
        return std::clamp(1 - sum * std::exp(lnPrefix), 0.0, 1.0);
    }
    // Modified Lentz evaluation of the continued fraction.
    const double tiny = 1e-300;
    double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
    for (int i = 1; i < 10000; ++i) {
        double an = -i * (i - a);
        b += 2;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1 / d;
        double delta = d * c;
        h *= delta;
        if (std::abs(delta - 1) < 1e-15) break;
    }
    return std::clamp(std::exp(lnPrefix) * h, 0.0, 1.0);
}

ChiSquareResult ChiSquareTest(std::span<const double> observed, std::span<const double> expected,
                              double significance, int numTests, double minExpected) {
    ChiSquareResult result;
    std::vector<size_t> order(observed.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return expected[a] < expected[b]; });

    // Pool low-expectation bins, then accumulate the statistic.
    double pooledObs = 0, pooledExp = 0, chsq = 0;
    int pooledBins = 0, dof = 0;
    for (size_t idx : order) {
        if (expected[idx] == 0) {
            if (observed[idx] > 1e-5 * observed.size()) {
                std::ostringstream os;
                os << "bin " << idx << " has " << observed[idx] << " samples but zero density";
                result.message = os.str();
                return result;
            }
        } else if (expected[idx] < minExpected) {
            pooledObs += observed[idx];
            pooledExp += expected[idx];
            ++pooledBins;
        } else if (pooledBins > 0 && pooledExp < minExpected) {
            // Fold the pool into this bin.
            double o = observed[idx] + pooledObs, e = expected[idx] + pooledExp;
            chsq += (o - e) * (o - e) / e;
            pooledObs = pooledExp = 0;
            pooledBins = 0;
            ++dof;
        } else {
            double diff = observed[idx] - expected[idx];
            chsq += diff * diff / expected[idx];
            ++dof;
        }
    }
    if (pooledExp > 0) {
        chsq += (pooledObs - pooledExp) * (pooledObs - pooledExp) / pooledExp;
        ++dof;
    }
    dof -= 1;
    result.statistic = chsq;
    result.degreesOfFreedom = dof;
    if (dof <= 0) {
        result.message = "too few bins with enough expected samples";
        return result;
    }
    result.pValue = ChiSquareSurvival(chsq, dof);
    double alpha = 1 - std::pow(1 - significance, 1.0 / numTests);
    result.passed = result.pValue >= alpha;
    if (!result.passed) {
        std::ostringstream os;
        os << "chi^2 = " << chsq << " with " << dof << " dof: p = " << result.pValue
           << " < alpha = " << alpha;
        result.message = os.str();
    }
    return result;
}

}  // namespace kiln
