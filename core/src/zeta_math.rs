// The series arithmetic of the Hurwitz zeta function, shared word for word by the library
// (`zeta.rs`) and by the build script that generates the precomputed table, so that the
// table and the run-time values agree bit for bit. Only `core` and `libm`: no std.

/// B_{2j} / (2j)! for j = 1..=10 (Bernoulli numbers over factorials).
const EM_COEFF: [f64; 10] = [
    1.0 / 12.0,
    -1.0 / 720.0,
    1.0 / 30240.0,
    -1.0 / 1209600.0,
    1.0 / 47900160.0,
    -691.0 / 1307674368000.0,
    1.0 / 74724249600.0,
    -3617.0 / 10670622842880000.0,
    43867.0 / 5109094217170944000.0,
    -174611.0 / 802857662698291200000.0,
];

/// B_{2j} / (2j) for j = 1..=10, for the digamma expansion.
const DIGAMMA_COEFF: [f64; 10] = [
    1.0 / 12.0,
    -1.0 / 120.0,
    1.0 / 252.0,
    -1.0 / 240.0,
    5.0 / 660.0,
    -691.0 / 32760.0,
    7.0 / 84.0,
    -3617.0 / 8160.0,
    43867.0 / 14364.0,
    -174611.0 / 6600.0,
];

/// Below this point the series is summed term by term; from it on, Euler–Maclaurin.
const EM_START: f64 = 12.0;

/// The Euler–Maclaurin expansion of zeta(s, x) for x >= EM_START, s != 1:
/// x^(1-s)/(s-1) + x^(-s)/2 + sum_j B_2j/(2j)! s(s+1)...(s+2j-2) x^(-s-2j+1).
/// For s < 1 this is the analytic continuation, whose differences are finite sums.
fn em_tail(s: f64, x: f64) -> f64 {
    let (small, xs) = em_small(s, x);
    small + x * xs / (s - 1.0)
}

/// The expansion without its leading term x^(1-s)/(s-1), and x^(-s).
fn em_small(s: f64, x: f64) -> (f64, f64) {
    let xs = libm::pow(x, -s);
    let inv_x2 = 1.0 / (x * x);
    let mut terms = [0.0f64; 10];
    // term_1 = s * x^(-s-1); term_{j+1} = term_j * (s+2j-1)(s+2j) / x^2.
    let mut rising = s * xs / x;
    for (j, (t, coeff)) in terms.iter_mut().zip(EM_COEFF.iter()).enumerate() {
        *t = coeff * rising;
        let k = (2 * j + 1) as f64;
        rising = rising * (s + k) * (s + k + 1.0) * inv_x2;
    }
    // Smallest terms first.
    let mut sum = 0.0f64;
    for t in terms.iter().rev() {
        sum += t;
    }
    (sum + 0.5 * xs, xs)
}

/// The asymptotic expansion of the digamma function for x >= EM_START.
fn digamma_asym(x: f64) -> f64 {
    let inv_x2 = 1.0 / (x * x);
    let mut p = inv_x2;
    let mut terms = [0.0f64; 10];
    for (t, coeff) in terms.iter_mut().zip(DIGAMMA_COEFF.iter()) {
        *t = coeff * p;
        p *= inv_x2;
    }
    let mut sum = 0.0f64;
    for t in terms.iter().rev() {
        sum += t;
    }
    libm::log(x) - 0.5 / x - sum
}

/// Number of leading terms summed directly so that a + m >= EM_START.
fn direct_terms(a: f64) -> u64 {
    if a >= EM_START {
        0
    } else {
        libm::ceil(EM_START - a) as u64
    }
}

/// Sum of (a+k)^(-s) for k in [from, to), smallest terms (largest k) first.
fn direct_sum(s: f64, a: f64, from: u64, to: u64) -> f64 {
    let mut sum = 0.0f64;
    let mut k = to;
    while k > from {
        k -= 1;
        sum += libm::pow(a + k as f64, -s);
    }
    sum
}

/// Hurwitz zeta for finite s > 1, finite a > 0 (not checked here).
fn hurwitz_raw(s: f64, a: f64) -> f64 {
    let m = direct_terms(a);
    em_tail(s, a + m as f64) + direct_sum(s, a, 0, m)
}

/// sum_{k=0}^{n} (a+k)^(-s) for finite s > 0, finite a > 0 (not checked here).
fn partial_raw(s: f64, a: f64, n: u64) -> f64 {
    let m = direct_terms(a);
    let count = n.saturating_add(1);
    if count <= m.saturating_add(64) {
        return direct_sum(s, a, 0, count);
    }
    let lo = a + m as f64;
    let hi = a + count as f64;
    // ln(hi / lo) from the exact count of terms, so that a huge a loses nothing.
    let log_ratio = libm::log1p((count - m) as f64 / lo);
    let tail = if s == 1.0 {
        // psi(hi) - psi(lo): ln(hi/lo) plus the small terms.
        log_ratio + (digamma_asym(hi) - libm::log(hi)) - (digamma_asym(lo) - libm::log(lo))
    } else {
        // The leading terms (lo^(1-s) - hi^(1-s)) / (s - 1), written with expm1 so that
        // neither s near 1 nor hi near lo cancels; then the small Euler–Maclaurin terms.
        let t = 1.0 - s;
        let lead = libm::pow(lo, t) * (libm::expm1(t * log_ratio) / t);
        lead + (em_small(s, lo).0 - em_small(s, hi).0)
    };
    tail + direct_sum(s, a, 0, m)
}
