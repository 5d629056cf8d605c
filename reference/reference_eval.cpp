#include "reference/reference_eval.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fxport::reference {

Range4 hull(const Range4& a, const Range4& b) {
    Range4 r;
    for (int c = 0; c < 4; ++c) {
        r.lo[c] = std::min(a.lo[c], b.lo[c]);
        r.hi[c] = std::max(a.hi[c], b.hi[c]);
    }
    r.exact = a.exact && b.exact;
    return r;
}

Range4 scaleByRange(V4 v, double s0, double s1) {
    Range4 r;
    for (int c = 0; c < 4; ++c) {
        double a = v[c] * s0, b = v[c] * s1;
        r.lo[c] = std::min(a, b);
        r.hi[c] = std::max(a, b);
    }
    return r;
}

int Eval::choose(int arity) {
    std::size_t p = next_++;
    if (arities_.size() <= p) arities_.resize(p + 1, 1);
    arities_[p] = arity;
    if (arity <= 1) return 0;
    return p < prefix_.size() ? std::min(prefix_[p], arity - 1) : 0;
}

bool Eval::decide(bool exact, double margin, double eps) {
    if (std::fabs(margin) < eps) return choose(2) ? !exact : exact;
    return exact;
}

V4 Eval::read(V4 value, V4 uncertainty) {
    int k = readIndex_++;
    if (logReads_) readLog_.push_back(uncertainty);
    if (k == perturbRead_) value[perturbChannel_] += perturbAmount_;
    return value;
}

Range4 Eval::read(Range4 value, V4 uncertainty) {
    int k = readIndex_++;
    if (logReads_) readLog_.push_back(uncertainty);
    if (k == perturbRead_) {
        value.lo[perturbChannel_] += perturbAmount_;
        value.hi[perturbChannel_] += perturbAmount_;
    }
    return value;
}

struct Evaluator {
    const PixelFunction& fn;
    const EvalOptions& options;

    Range4 run(Eval& ev) const {
        Range4 r = fn(ev);
        for (int c = 0; c < 4; ++c) {
            r.lo[c] = std::clamp(r.lo[c], options.clampLo, options.clampHi);
            r.hi[c] = std::clamp(r.hi[c], options.clampLo, options.clampHi);
        }
        return r;
    }

    static V4 change(const Range4& a, const Range4& b) {
        V4 d;
        for (int c = 0; c < 4; ++c) d[c] = std::max(std::fabs(a.lo[c] - b.lo[c]), std::fabs(a.hi[c] - b.hi[c]));
        return d;
    }
    static V4 max4(V4 a, V4 b) { return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z), std::max(a.w, b.w)}; }

    PixelResult evaluate() const {
        PixelResult out;
        // Every admissible decision path: depth-first over choose() positions.
        std::vector<std::vector<int>> stack{{}};
        Range4 all;
        Range4 nominal;
        std::vector<V4> reads;
        int leaves = 0;
        while (!stack.empty()) {
            std::vector<int> prefix = std::move(stack.back());
            stack.pop_back();
            Eval ev;
            ev.prefix_ = prefix;
            ev.logReads_ = leaves == 0;
            Range4 r = run(ev);
            if (leaves == 0) {
                nominal = r;
                all = r;
                reads = ev.readLog_;
            } else {
                all = hull(all, r);
            }
            if (++leaves > 1 << 14) throw std::runtime_error("reference pixel: too many ambiguous decisions");
            for (std::size_t p = prefix.size(); p < ev.arities_.size(); ++p)
                for (int c = 1; c < ev.arities_[p]; ++c) {
                    std::vector<int> child = prefix;
                    child.resize(p, 0);
                    child.push_back(c);
                    stack.push_back(std::move(child));
                }
        }
        out.lo = all.lo;
        out.hi = all.hi;
        out.exact = all.exact;
        out.leaves = leaves;

        // First-order effect of each read's uncertainty, channel by channel, both signs.
        V4 slack;
        for (std::size_t k = 0; k < reads.size(); ++k)
            for (int c = 0; c < 4; ++c) {
                double u = reads[k][c];
                if (!(u > 0)) continue;
                V4 worst;
                for (double sign : {1.0, -1.0}) {
                    Eval ev;
                    ev.perturbRead_ = int(k);
                    ev.perturbChannel_ = c;
                    ev.perturbAmount_ = sign * u;
                    worst = max4(worst, change(run(ev), nominal));
                }
                slack = slack + worst;
            }
        if (options.rasterSlack) {
            const double r = 1.0 / 512;
            for (V2 axis : {V2{1, 0}, V2{0, 1}}) {
                V4 worst;
                for (double sign : {1.0, -1.0}) {
                    Eval ev;
                    ev.shift_ = axis * (sign * r);
                    worst = max4(worst, change(run(ev), nominal));
                }
                slack = slack + worst;
            }
        }
        out.slack = slack;
        return out;
    }
};

PixelResult evaluatePixel(const PixelFunction& fn, const EvalOptions& options) {
    return Evaluator{fn, options}.evaluate();
}

}  // namespace fxport::reference
