// Construction of clifford::Algebra: metric, change of basis to an orthogonal basis, blade names.
#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "pgamesh/algebra/clifford/algebra.hpp"

namespace pgamesh::clifford {

namespace {

char suffix_char(int index) {
  return index < 10 ? static_cast<char>('0' + index) : static_cast<char>('A' + (index - 10));
}

// Cyclic Jacobi eigen-decomposition of a symmetric matrix: a = Q diag(values) Qᵀ, Q column-wise
// eigenvectors (q[i*n + k] = Q_ik).
void jacobi_eigen(std::vector<double> a, int n, std::vector<double>& values,
                  std::vector<double>& q) {
  q.assign(static_cast<std::size_t>(n * n), 0.0);
  for (int i = 0; i < n; ++i) q[static_cast<std::size_t>(i * n + i)] = 1.0;
  auto at = [n](std::vector<double>& m, int i, int j) -> double& {
    return m[static_cast<std::size_t>(i * n + j)];
  };
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0, scale = 0;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) (i == j ? scale : off) += at(a, i, j) * at(a, i, j);
    if (off <= 1e-30 * (scale + off)) break;
    for (int p = 0; p < n; ++p)
      for (int r = p + 1; r < n; ++r) {
        const double apr = at(a, p, r);
        if (apr == 0) continue;
        const double tau = (at(a, r, r) - at(a, p, p)) / (2 * apr);
        const double t = (tau >= 0 ? 1.0 : -1.0) / (std::abs(tau) + std::sqrt(1 + tau * tau));
        const double c = 1 / std::sqrt(1 + t * t), s = t * c;
        for (int k = 0; k < n; ++k) {  // a ← a G (columns p, r)
          const double akp = at(a, k, p), akr = at(a, k, r);
          at(a, k, p) = c * akp - s * akr;
          at(a, k, r) = s * akp + c * akr;
        }
        for (int k = 0; k < n; ++k) {  // a ← Gᵀ a (rows p, r)
          const double apk = at(a, p, k), ark = at(a, r, k);
          at(a, p, k) = c * apk - s * ark;
          at(a, r, k) = s * apk + c * ark;
        }
        for (int k = 0; k < n; ++k) {
          const double qkp = at(q, k, p), qkr = at(q, k, r);
          at(q, k, p) = c * qkp - s * qkr;
          at(q, k, r) = s * qkp + c * qkr;
        }
      }
  }
  values.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) values[static_cast<std::size_t>(i)] = at(a, i, i);
}

std::vector<std::string> split(std::string_view s, char sep) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t pos = s.find(sep, start);
    out.emplace_back(s.substr(start, pos == std::string_view::npos ? pos : pos - start));
    if (pos == std::string_view::npos) return out;
    start = pos + 1;
  }
}

// Outermorphism of the linear map given by `images` (generator i ↦ images[i]): each blade is the
// outer product of its generators' images, expanded factor by factor. Partial expansions are
// merged only when they grow (null pairs make equal blades that cancel or combine).
Multivector outermorphism(const Multivector& a, const std::vector<SparseVector>& images) {
  std::vector<Term> out, cur, next;
  for (const Term& t : a.terms) {
    cur.assign(1, Term{0, t.coeff});
    for (BladeMask rest = t.mask; rest != 0; rest &= rest - 1) {
      const int i = std::countr_zero(rest);
      next.clear();
      for (const Term& c : cur)
        for (const auto& [k, v] : images[static_cast<std::size_t>(i)]) {
          const BladeMask bit = BladeMask{1} << k;
          if (c.mask & bit) continue;
          next.push_back({c.mask | bit, c.coeff * v * reorder_sign(c.mask, bit)});
        }
      if (next.size() > 8) {
        std::sort(next.begin(), next.end(),
                  [](const Term& x, const Term& y) { return x.mask < y.mask; });
        std::size_t w = 0;
        for (std::size_t r = 0; r < next.size(); ++r) {
          if (w > 0 && next[w - 1].mask == next[r].mask)
            next[w - 1].coeff += next[r].coeff;
          else
            next[w++] = next[r];
        }
        next.resize(w);
      }
      std::swap(cur, next);
    }
    out.insert(out.end(), cur.begin(), cur.end());
  }
  return from_terms(std::move(out));
}
}  // namespace

Algebra Algebra::signature(int p, int q, int r) {
  if (p < 0 || q < 0 || r < 0 || p + q + r < 1 || p + q + r > max_generators)
    throw std::invalid_argument("signature (" + std::to_string(p) + "," + std::to_string(q) + "," +
                                std::to_string(r) + "): need 1 to " +
                                std::to_string(max_generators) + " generators");
  std::vector<double> squares;
  squares.insert(squares.end(), static_cast<std::size_t>(r), 0.0);
  squares.insert(squares.end(), static_cast<std::size_t>(p), 1.0);
  squares.insert(squares.end(), static_cast<std::size_t>(q), -1.0);
  const int first = (r == 1) ? 0 : 1;
  std::vector<std::string> names;
  for (int i = 0; i < p + q + r; ++i) names.push_back(std::string("e") + suffix_char(first + i));
  return diagonal(std::move(squares), std::move(names));
}

Algebra Algebra::diagonal(std::vector<double> squares, std::vector<std::string> names) {
  const int n = static_cast<int>(squares.size());
  std::vector<std::vector<double>> gram(squares.size(), std::vector<double>(squares.size(), 0.0));
  for (int i = 0; i < n; ++i)
    gram[static_cast<std::size_t>(i)][static_cast<std::size_t>(i)] =
        squares[static_cast<std::size_t>(i)];
  return bilinear_form(std::move(gram), std::move(names));
}

Algebra Algebra::bilinear_form(std::vector<std::vector<double>> gram,
                               std::vector<std::string> names) {
  const int n = static_cast<int>(gram.size());
  if (n < 1 || n > max_generators)
    throw std::invalid_argument("bilinear form: need 1 to " + std::to_string(max_generators) +
                                " generators, got " + std::to_string(n));
  if (names.size() != gram.size())
    throw std::invalid_argument("bilinear form: " + std::to_string(names.size()) + " names for " +
                                std::to_string(n) + " generators");
  Algebra alg;
  alg.n_ = n;
  alg.full_mask_ = (BladeMask{1} << n) - 1;
  alg.names_ = std::move(names);
  for (std::size_t i = 0; i < alg.names_.size(); ++i) {
    const std::string& nm = alg.names_[i];
    if (nm.empty() || nm == "1" || nm.find('^') != std::string::npos)
      throw std::invalid_argument("bilinear form: bad generator name '" + nm + "'");
    for (std::size_t j = 0; j < i; ++j)
      if (alg.names_[j] == nm)
        throw std::invalid_argument("bilinear form: generator name '" + nm + "' repeated");
  }
  alg.gram_.resize(static_cast<std::size_t>(n * n));
  for (int i = 0; i < n; ++i) {
    if (static_cast<int>(gram[static_cast<std::size_t>(i)].size()) != n)
      throw std::invalid_argument("bilinear form: the Gram matrix is not square");
    for (int j = 0; j < n; ++j) {
      const double g = gram[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
      if (!std::isfinite(g) || g != gram[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)])
        throw std::invalid_argument("bilinear form: the Gram matrix is not symmetric and finite");
      alg.gram_[static_cast<std::size_t>(i * n + j)] = g;
    }
  }
  alg.finish();
  return alg;
}

void Algebra::finish() {
  const auto N = static_cast<std::size_t>(n_);
  auto g = [this](int i, int j) { return inner(i, j); };
  diagonal_ = true;
  for (int i = 0; i < n_; ++i)
    for (int j = 0; j < n_; ++j)
      if (i != j && g(i, j) != 0) diagonal_ = false;
  squares_.assign(N, 0.0);
  to_orthogonal_.assign(N, {});
  from_orthogonal_.assign(N, {});
  if (diagonal_) {
    for (int i = 0; i < n_; ++i) {
      squares_[static_cast<std::size_t>(i)] = g(i, i);
      to_orthogonal_[static_cast<std::size_t>(i)] = {{i, 1.0}};
      from_orthogonal_[static_cast<std::size_t>(i)] = {{i, 1.0}};
    }
  } else {
    // Isolated null pairs (u_a² = u_b² = 0, u_a·u_b = c, both orthogonal to everything else) get
    // the exact map u_a = ½(f₋ − f₊), u_b = −c (f₊ + f₋) with f₊ = f_a, f₋ = f_b
    // (docs/conventions.md §15 for c = −1); everything else orthogonal keeps its generator.
    std::vector<int> partner(N, -1);
    bool pairs_only = true;
    for (int i = 0; i < n_ && pairs_only; ++i) {
      int others = 0;
      for (int j = 0; j < n_; ++j)
        if (j != i && g(i, j) != 0) {
          ++others;
          partner[static_cast<std::size_t>(i)] = j;
        }
      const int j = partner[static_cast<std::size_t>(i)];
      if (others > 1 || (others == 1 && (g(i, i) != 0 || g(j, j) != 0))) pairs_only = false;
    }
    if (pairs_only) {
      for (int i = 0; i < n_; ++i) {
        const int j = partner[static_cast<std::size_t>(i)];
        const auto I = static_cast<std::size_t>(i);
        if (j < 0) {
          squares_[I] = g(i, i);
          to_orthogonal_[I] = {{i, 1.0}};
          from_orthogonal_[I] = {{i, 1.0}};
        } else if (i < j) {
          const double c = g(i, j);
          const auto J = static_cast<std::size_t>(j);
          squares_[I] = 1.0;   // f₊ = f_i
          squares_[J] = -1.0;  // f₋ = f_j
          to_orthogonal_[I] = {{i, -0.5}, {j, 0.5}};
          to_orthogonal_[J] = {{i, -c}, {j, -c}};
          from_orthogonal_[I] = {{i, -1.0}, {j, -0.5 / c}};  // f₊ = −u_a − u_b/(2c)
          from_orthogonal_[J] = {{i, 1.0}, {j, -0.5 / c}};   // f₋ = u_a − u_b/(2c)
        }
      }
    } else {
      // General form: G = Q Λ Qᵀ; f_k = Σ_i Q_ik u_i / sqrt|λ_k| has f_k² = sign λ_k, and
      // u_i = Σ_k Q_ik sqrt|λ_k| f_k.
      std::vector<double> values, q;
      jacobi_eigen(gram_, n_, values, q);
      double scale = 0;
      for (double v : values) scale = std::max(scale, std::abs(v));
      for (int k = 0; k < n_; ++k) {
        const double lam = values[static_cast<std::size_t>(k)];
        const bool null = std::abs(lam) <= 1e-14 * scale;
        const double root = null ? 1.0 : std::sqrt(std::abs(lam));
        squares_[static_cast<std::size_t>(k)] = null ? 0.0 : (lam > 0 ? 1.0 : -1.0);
        for (int i = 0; i < n_; ++i) {
          const double qik = q[static_cast<std::size_t>(i * n_ + k)];
          if (qik == 0) continue;
          to_orthogonal_[static_cast<std::size_t>(i)].push_back({k, qik * root});
          from_orthogonal_[static_cast<std::size_t>(k)].push_back({i, qik / root});
        }
      }
    }
  }
  unit_metric_ = true;
  negative_mask_ = null_mask_ = 0;
  for (int k = 0; k < n_; ++k) {
    const double s = squares_[static_cast<std::size_t>(k)];
    if (s == -1.0) negative_mask_ |= BladeMask{1} << k;
    if (s == 0.0) null_mask_ |= BladeMask{1} << k;
    if (s != 1.0 && s != -1.0 && s != 0.0) unit_metric_ = false;
  }
  table_.clear();
  to_orthogonal_images_.clear();
  from_orthogonal_images_.clear();
  if (n_ <= small_generators && !diagonal_) {
    const std::size_t size = std::size_t{1} << n_;
    for (BladeMask m = 0; m < size; ++m) {
      to_orthogonal_images_.push_back(outermorphism(basis_blade(m), to_orthogonal_));
      from_orthogonal_images_.push_back(outermorphism(basis_blade(m), from_orthogonal_));
    }
  }
  if (n_ <= small_generators) {
    const std::size_t size = std::size_t{1} << n_;
    std::vector<double> t(size * size);
    for (BladeMask a = 0; a < size; ++a)
      for (BladeMask b = 0; b < size; ++b)
        t[a * size + b] = reorder_sign(a, b) * metric_weight(a & b);
    table_ = std::move(t);
  }
  concatenated_names_ = diagonal_;
  for (int i = 0; i < n_ && concatenated_names_; ++i) {
    const std::string& nm = names_[static_cast<std::size_t>(i)];
    if (nm.size() != 2 || nm[0] != 'e') concatenated_names_ = false;
    for (int j = 0; j < i && concatenated_names_; ++j)
      if (names_[static_cast<std::size_t>(j)][1] == nm[1]) concatenated_names_ = false;
  }
}

double Algebra::metric_weight(BladeMask common) const {
  if (unit_metric_) {
    if (common & null_mask_) return 0.0;
    return odd_parity(common & negative_mask_) ? -1.0 : 1.0;
  }
  double w = 1;
  for (int k = 0; common != 0; ++k, common >>= 1)
    if (common & 1) w *= squares_[static_cast<std::size_t>(k)];
  return w;
}

std::string Algebra::concatenated_or_joined(BladeMask mask) const {
  if (mask == 0) return "1";
  std::string s = concatenated_names_ ? "e" : "";
  for (int i = 0; i < n_; ++i) {
    if (!(mask >> i & 1)) continue;
    if (concatenated_names_) {
      s += names_[static_cast<std::size_t>(i)][1];
    } else {
      if (!s.empty()) s += '^';
      s += names_[static_cast<std::size_t>(i)];
    }
  }
  return s;
}

std::pair<std::string, double> Algebra::blade_name(BladeMask mask) const {
  if (!custom_names_.empty() && !custom_names_[mask].empty())
    return {custom_names_[mask], custom_signs_[mask]};
  return {concatenated_or_joined(mask), 1.0};
}

void Algebra::add_generator_alias(const std::string& alias, int generator) {
  aliases_.emplace_back(alias, generator);
}

std::optional<std::pair<BladeMask, double>> Algebra::parse_blade(std::string_view name) const {
  if (name == "1") return std::pair<BladeMask, double>{0, 1.0};
  if (!custom_names_.empty())
    for (std::size_t m = 0; m < custom_names_.size(); ++m)
      if (custom_names_[m] == name)
        return std::pair<BladeMask, double>{static_cast<BladeMask>(m), custom_signs_[m]};
  auto generator = [this](std::string_view nm) -> int {
    for (int i = 0; i < n_; ++i)
      if (names_[static_cast<std::size_t>(i)] == nm) return i;
    for (const auto& [alias, index] : aliases_)
      if (alias == nm) return index;
    return -1;
  };
  std::vector<int> factors;
  if (const int g = generator(name); g >= 0) {
    factors.push_back(g);
  } else if (name.find('^') != std::string_view::npos) {
    for (const std::string& part : split(name, '^')) {
      const int gi = generator(part);
      if (gi < 0) return std::nullopt;
      factors.push_back(gi);
    }
  } else if (concatenated_names_ && name.size() >= 2 && name[0] == 'e') {
    for (char c : name.substr(1)) {
      int gi = -1;
      for (int i = 0; i < n_; ++i)
        if (names_[static_cast<std::size_t>(i)][1] == c) gi = i;
      if (gi < 0) return std::nullopt;
      factors.push_back(gi);
    }
  } else {
    return std::nullopt;
  }
  BladeMask mask = 0;
  double sign = 1;
  for (int f : factors) {
    const BladeMask bit = BladeMask{1} << f;
    if (mask & bit) return std::nullopt;  // repeated factor: not a basis blade
    sign *= reorder_sign(mask, bit);
    mask |= bit;
  }
  return std::pair<BladeMask, double>{mask, sign};
}

void Algebra::set_blade_names(const std::vector<std::string>& names) {
  std::vector<std::string> custom(std::size_t{1} << n_);
  std::vector<double> signs(std::size_t{1} << n_, 1.0);
  for (const std::string& nm : names) {
    const auto parsed = parse_blade(nm);
    if (!parsed) throw std::invalid_argument("blade name '" + nm + "' is not a blade");
    custom[parsed->first] = nm;
    signs[parsed->first] = parsed->second;
  }
  std::vector<int> rank(std::size_t{1} << n_, static_cast<int>(names.size()));
  for (std::size_t i = 0; i < names.size(); ++i)
    rank[parse_blade(names[i])->first] = static_cast<int>(i);
  custom_names_ = std::move(custom);
  custom_signs_ = std::move(signs);
  custom_rank_ = std::move(rank);
}

bool Algebra::display_before(BladeMask a, BladeMask b) const {
  if (!custom_rank_.empty() && custom_rank_[a] != custom_rank_[b])
    return custom_rank_[a] < custom_rank_[b];
  if (grade_of(a) != grade_of(b)) return grade_of(a) < grade_of(b);
  const BladeMask d = a ^ b;
  return (a & d & (~d + 1)) != 0;  // the lowest differing factor comes first
}

std::vector<std::pair<std::string, double>> Algebra::named_coefficients(
    const Multivector& a) const {
  std::vector<std::pair<std::string, double>> out;
  out.reserve(a.terms.size());
  for (const Term& t : a.terms) {
    auto [nm, sign] = blade_name(t.mask);
    out.emplace_back(std::move(nm), sign * t.coeff);
  }
  return out;
}

Multivector Algebra::to_orthogonal(const Multivector& a) const {
  return diagonal_ ? a : outermorphism(a, to_orthogonal_);
}
Multivector Algebra::from_orthogonal(const Multivector& a) const {
  return diagonal_ ? a : outermorphism(a, from_orthogonal_);
}

std::optional<Algebra> make_algebra(std::string_view name) {
  auto null_pairs = [](const std::vector<std::string>& names,
                       const std::vector<std::pair<int, int>>& pairs, double c,
                       const std::vector<double>& squares) {
    std::vector<std::vector<double>> gram(names.size(), std::vector<double>(names.size(), 0.0));
    for (std::size_t i = 0; i < names.size(); ++i) gram[i][i] = squares[i];
    for (auto [a, b] : pairs) {
      gram[static_cast<std::size_t>(a)][static_cast<std::size_t>(b)] = c;
      gram[static_cast<std::size_t>(b)][static_cast<std::size_t>(a)] = c;
    }
    return Algebra::bilinear_form(std::move(gram), names);
  };
  if (name == "pga2") {
    Algebra a = Algebra::signature(2, 0, 1);
    a.set_blade_names({"1", "e0", "e1", "e2", "e01", "e20", "e12", "e012"});
    return a;
  }
  if (name == "pga3") {
    Algebra a = Algebra::signature(3, 0, 1);
    a.set_blade_names({"1", "e0", "e1", "e2", "e3", "e01", "e02", "e03", "e12", "e31", "e23",
                       "e021", "e013", "e032", "e123", "e0123"});
    return a;
  }
  if (name.size() == 4 && name.substr(0, 3) == "pga" && name[3] >= '1' && name[3] <= '6')
    return Algebra::signature(name[3] - '0', 0, 1);
  if (name == "cga3" || name == "cga") {
    // docs/conventions.md §15: basis order eo, e1, e2, e3, e∞ with eo·e∞ = −1.
    Algebra a = null_pairs({"eo", "e1", "e2", "e3", "ei"}, {{0, 4}}, -1.0, {0, 1, 1, 1, 0});
    a.add_generator_alias("einf", 4);
    return a;
  }
  if (name == "dpga") {  // docs/conventions.md §16: w_i · w_j* = ½ δ_ij
    return null_pairs({"w0", "w1", "w2", "w3", "w0s", "w1s", "w2s", "w3s"},
                      {{0, 4}, {1, 5}, {2, 6}, {3, 7}}, 0.5, std::vector<double>(8, 0.0));
  }
  if (name == "dcga") {
    Algebra a = null_pairs({"eo1", "e1", "e2", "e3", "ei1", "eo2", "e4", "e5", "e6", "ei2"},
                           {{0, 4}, {5, 9}}, -1.0, {0, 1, 1, 1, 0, 0, 1, 1, 1, 0});
    a.add_generator_alias("einf1", 4);
    a.add_generator_alias("einf2", 9);
    return a;
  }
  if (name == "qcga") {
    std::vector<std::string> names = {"e1", "e2", "e3"};
    std::vector<std::pair<int, int>> pairs;
    for (int i = 1; i <= 6; ++i) names.push_back("eo" + std::to_string(i));
    for (int i = 1; i <= 6; ++i) names.push_back("ei" + std::to_string(i));
    for (int i = 0; i < 6; ++i) pairs.emplace_back(3 + i, 9 + i);
    std::vector<double> squares(15, 0.0);
    squares[0] = squares[1] = squares[2] = 1.0;
    Algebra a = null_pairs(names, pairs, -1.0, squares);
    for (int i = 1; i <= 6; ++i) a.add_generator_alias("einf" + std::to_string(i), 8 + i);
    return a;
  }
  // "p,q,r" or "p,q"
  const std::vector<std::string> parts = split(name, ',');
  if (parts.size() == 2 || parts.size() == 3) {
    int v[3] = {0, 0, 0};
    for (std::size_t i = 0; i < parts.size(); ++i) {
      if (parts[i].empty() || parts[i].size() > 2 ||
          !std::all_of(parts[i].begin(), parts[i].end(),
                       [](char c) { return c >= '0' && c <= '9'; }))
        return std::nullopt;
      v[i] = std::stoi(parts[i]);
    }
    if (v[0] + v[1] + v[2] < 1 || v[0] + v[1] + v[2] > Algebra::max_generators) return std::nullopt;
    return Algebra::signature(v[0], v[1], v[2]);
  }
  return std::nullopt;
}

}  // namespace pgamesh::clifford
