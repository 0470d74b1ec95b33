#include "contact/ContactCondensation.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"

namespace choc {

// The active constraints grouped by slave node, each node's C = Q R by Gram-Schmidt.
void ContactCondensation::groupActive(const Map& rowMap) {
  nodes_.clear();
  std::map<int, int> index;  // slave node -> nodes_
  const auto& cs = contact_.constraints();
  for (int s = 0; s < int(cs.size()); ++s) {
    if (!contact_.status()[s]) continue;
    const auto [it, fresh] = index.emplace(cs[s].geometry.slaveNode, int(nodes_.size()));
    if (fresh) nodes_.emplace_back();
    Node& n = nodes_[it->second];
    n.constraints.push_back(s);
    for (const auto& t : cs[s].terms) n.dofs.push_back(t.first);
  }
  for (Node& n : nodes_) {
    std::sort(n.dofs.begin(), n.dofs.end());
    n.dofs.erase(std::unique(n.dofs.begin(), n.dofs.end()), n.dofs.end());
    const size_t k = n.dofs.size(), m = n.constraints.size();
    n.Q.assign(k * m, 0.0);
    n.R.assign(m * m, 0.0);
    for (size_t j = 0; j < m; ++j) {
      double* v = &n.Q[j * k];
      for (const auto& [dof, coef] : cs[n.constraints[j]].terms)
        v[std::lower_bound(n.dofs.begin(), n.dofs.end(), dof) - n.dofs.begin()] += coef;
      double before = 0.0;
      for (size_t a = 0; a < k; ++a) before += v[a] * v[a];
      for (size_t i = 0; i < j; ++i) {
        double dot = 0.0;
        for (size_t a = 0; a < k; ++a) dot += n.Q[i * k + a] * v[a];
        n.R[j * m + i] = dot;
        for (size_t a = 0; a < k; ++a) v[a] -= dot * n.Q[i * k + a];
      }
      double norm = 0.0;
      for (size_t a = 0; a < k; ++a) norm += v[a] * v[a];
      norm = std::sqrt(norm);
      if (!(norm > 1e-8 * std::sqrt(before)) || before == 0.0)
        throw NumericalError("contact: the active constraints of slave node " +
                             std::to_string(cs[n.constraints[j]].geometry.slaveNode + 1) +
                             " are linearly dependent (normals parallel, or along fixed components)");
      n.R[j * m + j] = norm;
      for (size_t a = 0; a < k; ++a) v[a] /= norm;
    }
    n.P.assign(k * k, 0.0);
    for (size_t a = 0; a < k; ++a) {
      n.P[a * k + a] = 1.0;
      for (size_t b = 0; b < k; ++b)
        for (size_t j = 0; j < m; ++j) n.P[a * k + b] -= n.Q[j * k + a] * n.Q[j * k + b];
    }
    for (GO d : n.dofs) {
      const LO l = rowMap.getLocalElement(d);
      if (l == Teuchos::OrdinalTraits<LO>::invalid()) {
        n.rows.clear();
        break;
      }
      n.rows.push_back(l);
    }
  }
}

namespace {

// The inverse of a small dense m x m matrix (column-major), by Gauss-Jordan with partial pivoting;
// false when singular.
bool invert(std::vector<double> a, size_t m, std::vector<double>& inv) {
  inv.assign(m * m, 0.0);
  for (size_t i = 0; i < m; ++i) inv[i * m + i] = 1.0;
  for (size_t c = 0; c < m; ++c) {
    size_t p = c;
    for (size_t r = c + 1; r < m; ++r)
      if (std::abs(a[c * m + r]) > std::abs(a[c * m + p])) p = r;
    if (!(std::abs(a[c * m + p]) > 0.0)) return false;
    for (size_t k = 0; k < m; ++k) {
      std::swap(a[k * m + c], a[k * m + p]);
      std::swap(inv[k * m + c], inv[k * m + p]);
    }
    const double d = a[c * m + c];
    for (size_t k = 0; k < m; ++k) {
      a[k * m + c] /= d;
      inv[k * m + c] /= d;
    }
    for (size_t r = 0; r < m; ++r) {
      if (r == c) continue;
      const double f = a[c * m + r];
      if (f == 0.0) continue;
      for (size_t k = 0; k < m; ++k) {
        a[k * m + r] -= f * a[k * m + c];
        inv[k * m + r] -= f * inv[k * m + c];
      }
    }
  }
  return true;
}

}  // namespace

void ContactCondensation::project(const RCP<CrsMatrix>& A, const std::vector<MatrixEntry>& multiplierColumns,
                                  GO multiplierBase) {
  matrix_ = A;
  sigma_ = contact_.activeSet().scale;
  groupActive(*A->getRowMap());
  addFriction(multiplierColumns, multiplierBase);
  projectColumns(*A);
  projectRows(*A);
}

// V = C + (friction's entries in the multipliers' columns, as -sigma V), then P_L and (Q^T V)^-1.
// Without such entries V = C = Q R: P_L = P.
void ContactCondensation::addFriction(const std::vector<MatrixEntry>& multiplierColumns, GO multiplierBase) {
  std::map<int, std::pair<int, int>> where;  // constraint -> (node, column)
  for (size_t n = 0; n < nodes_.size(); ++n)
    for (size_t j = 0; j < nodes_[n].constraints.size(); ++j) where[nodes_[n].constraints[j]] = {int(n), int(j)};
  std::vector<std::vector<double>> V(nodes_.size());
  for (Node& n : nodes_) {  // C = Q R
    const size_t dim = n.dofs.size(), m = n.constraints.size();
    std::vector<double>& v = V[&n - nodes_.data()];
    v.assign(dim * m, 0.0);
    for (size_t j = 0; j < m; ++j)
      for (size_t i = 0; i <= j; ++i)
        for (size_t a = 0; a < dim; ++a) v[j * dim + a] += n.Q[i * dim + a] * n.R[j * m + i];
  }
  for (const MatrixEntry& e : multiplierColumns) {
    const auto it = where.find(int(e.col - multiplierBase));
    if (it == where.end()) continue;  // an inactive node's column: no unknown
    Node& n = nodes_[it->second.first];
    const auto at = std::lower_bound(n.dofs.begin(), n.dofs.end(), e.row);
    if (at == n.dofs.end() || *at != e.row)
      throw std::logic_error("contact condensation: a multiplier's column reaches another node's row");
    V[it->second.first][size_t(it->second.second) * n.dofs.size() + size_t(at - n.dofs.begin())] -= e.value / sigma_;
  }
  for (Node& n : nodes_) {
    const size_t dim = n.dofs.size(), m = n.constraints.size();
    const std::vector<double>& v = V[&n - nodes_.data()];
    std::vector<double> qtv(m * m, 0.0);  // (Q^T V)(i, j)
    for (size_t j = 0; j < m; ++j)
      for (size_t i = 0; i < m; ++i)
        for (size_t a = 0; a < dim; ++a) qtv[j * m + i] += n.Q[i * dim + a] * v[j * dim + a];
    if (!invert(qtv, m, n.QtVinv))
      throw NumericalError("contact: the friction of slave node " +
                           std::to_string(contact_.constraints()[n.constraints[0]].geometry.slaveNode + 1) +
                           " makes its condensed constraints singular");
    n.PL.assign(dim * dim, 0.0);
    for (size_t a = 0; a < dim; ++a) {
      n.PL[a * dim + a] = 1.0;
      for (size_t b = 0; b < dim; ++b)  // - sum_ij V(a, i) inv(i, j) Q(b, j)
        for (size_t i = 0; i < m; ++i)
          for (size_t j = 0; j < m; ++j) n.PL[a * dim + b] -= v[i * dim + a] * n.QtVinv[j * m + i] * n.Q[j * dim + b];
    }
  }
}

void ContactCondensation::projectColumns(CrsMatrix& A) {
  columns_.clear();
  const auto colMap = A.getColMap();
  std::vector<int> colNode(colMap->getNodeNumElements(), -1), colPos(colMap->getNodeNumElements(), -1);
  for (size_t n = 0; n < nodes_.size(); ++n)
    for (size_t i = 0; i < nodes_[n].dofs.size(); ++i) {
      const LO c = colMap->getLocalElement(nodes_[n].dofs[i]);
      if (c == Teuchos::OrdinalTraits<LO>::invalid()) continue;
      colNode[c] = int(n);
      colPos[c] = int(i);
    }
  const auto L = A.getLocalMatrixHost();
  // W's rows at the nodes, before projection (the multipliers are read from them).
  for (Node& n : nodes_) {
    n.wRows.assign(n.rows.size(), {});
    for (size_t a = 0; a < n.rows.size(); ++a)
      for (auto k = L.graph.row_map(n.rows[a]); k < L.graph.row_map(n.rows[a] + 1); ++k)
        n.wRows[a].push_back({L.graph.entries(k), L.values(k)});
  }
  struct Hit {
    int node, pos;
    size_t k;
  };
  std::vector<Hit> hits;
  const size_t nRows = L.graph.row_map.extent(0) - 1;
  for (size_t i = 0; i < nRows; ++i) {
    hits.clear();
    for (auto k = L.graph.row_map(i); k < L.graph.row_map(i + 1); ++k) {
      const LO c = L.graph.entries(k);
      if (colNode[c] < 0) continue;
      columns_.push_back({LO(i), colNode[c], colPos[c], L.values(k)});
      hits.push_back({colNode[c], colPos[c], size_t(k)});
    }
    std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.node < b.node; });
    for (size_t h = 0; h < hits.size();) {
      const Node& n = nodes_[hits[h].node];
      const size_t dim = n.dofs.size();
      double v[3] = {0, 0, 0}, w[3] = {0, 0, 0};
      long at[3] = {-1, -1, -1};
      size_t e = h;
      for (; e < hits.size() && hits[e].node == hits[h].node; ++e) {
        v[hits[e].pos] = L.values(hits[e].k);
        at[hits[e].pos] = long(hits[e].k);
      }
      for (size_t a = 0; a < dim; ++a)
        for (size_t b = 0; b < dim; ++b) w[a] += n.P[a * dim + b] * v[b];
      for (size_t a = 0; a < dim; ++a) {
        if (at[a] >= 0) L.values(at[a]) = w[a];
        else if (w[a] != 0.0)
          throw std::logic_error("contact condensation: the matrix graph lacks a component of a contact node");
      }
      h = e;
    }
  }
}

void ContactCondensation::projectRows(CrsMatrix& A) {
  const auto L = A.getLocalMatrixHost();
  const auto colMap = A.getColMap();
  for (const Node& n : nodes_) {
    if (n.rows.empty()) continue;
    const size_t dim = n.dofs.size(), m = n.constraints.size();
    const auto b0 = L.graph.row_map(n.rows[0]), len = L.graph.row_map(n.rows[0] + 1) - b0;
    size_t begin[3] = {0, 0, 0};
    for (size_t a = 0; a < dim; ++a) {
      begin[a] = size_t(L.graph.row_map(n.rows[a]));
      bool same = L.graph.row_map(n.rows[a] + 1) - begin[a] == len;
      for (size_t j = 0; same && j < size_t(len); ++j) same = L.graph.entries(begin[a] + j) == L.graph.entries(b0 + j);
      if (!same) throw std::logic_error("contact condensation: the rows of a contact node differ in pattern");
    }
    for (size_t j = 0; j < size_t(len); ++j) {
      double v[3] = {0, 0, 0};
      for (size_t a = 0; a < dim; ++a) v[a] = L.values(begin[a] + j);
      const LO col = L.graph.entries(b0 + j);
      const GO gcol = colMap->getGlobalElement(col);
      const auto at = std::lower_bound(n.dofs.begin(), n.dofs.end(), gcol);
      const long self = at != n.dofs.end() && *at == gcol ? long(at - n.dofs.begin()) : -1;
      for (size_t a = 0; a < dim; ++a) {
        double w = 0.0;
        for (size_t b = 0; b < dim; ++b) w += n.PL[a * dim + b] * v[b];
        if (self >= 0)  // sigma Q Q^T on the node's own block
          for (size_t q = 0; q < m; ++q) w += sigma_ * n.Q[q * dim + a] * n.Q[q * dim + size_t(self)];
        L.values(begin[a] + j) = w;
      }
    }
  }
}

void ContactCondensation::rightHandSide(const Vector& r, const Vector& u, MultiVector& b) {
  const std::vector<double> g = contact_.gaps(u);
  const double S = contact_.activeSet().scale;
  auto rd = r.getData();
  auto bd = b.getDataNonConst(0);
  for (size_t i = 0; i < r.getLocalLength(); ++i) bd[i] = -rd[i];
  for (Node& n : nodes_) {  // d0 = C (C^T C)^-1 t = Q R^-T t
    const size_t dim = n.dofs.size(), m = n.constraints.size();
    std::vector<double> y(m, 0.0);
    for (size_t j = 0; j < m; ++j) {
      double t = contact_.activeSet().rowResidual(n.constraints[j], g[n.constraints[j]]) / S;
      for (size_t i = 0; i < j; ++i) t -= n.R[j * m + i] * y[i];
      y[j] = t / n.R[j * m + j];
    }
    n.d0.assign(dim, 0.0);
    for (size_t j = 0; j < m; ++j)
      for (size_t a = 0; a < dim; ++a) n.d0[a] += n.Q[j * dim + a] * y[j];
  }
  for (const ColumnEntry& e : columns_) bd[e.row] -= e.value * nodes_[e.node].d0[e.pos];
  for (Node& n : nodes_) {
    const size_t dim = n.rows.size();
    n.r.assign(dim, 0.0);
    double w[3] = {0, 0, 0};
    for (size_t a = 0; a < dim; ++a) {
      w[a] = bd[n.rows[a]];
      n.r[a] = rd[n.rows[a]];
    }
    for (size_t a = 0; a < dim; ++a) {
      double p = sigma_ * n.d0[a];
      for (size_t c = 0; c < dim; ++c) p += n.PL[a * dim + c] * w[c];
      bd[n.rows[a]] = p;
    }
  }
}

// V dlambda = (W du + R) at each node: dlambda = (Q^T V)^-1 Q^T z (R^-1 Q^T z without friction).
void ContactCondensation::takeSolution(const MultiVector& x, Vector& du) const {
  {  // du = P x + d0 at the nodes: their constrained part exact whatever the solver's tolerance
    auto xd = x.getData(0);
    auto d = du.getDataNonConst();
    for (size_t i = 0; i < du.getLocalLength(); ++i) d[i] = xd[i];
    for (const Node& n : nodes_)
      for (size_t a = 0; a < n.rows.size(); ++a) {
        double p = n.d0[a];
        for (size_t b = 0; b < n.rows.size(); ++b) p += n.P[a * n.rows.size() + b] * xd[n.rows[b]];
        d[n.rows[a]] = p;
      }
  }
  Vector onColumns(matrix_->getColMap());
  const auto importer = matrix_->getGraph()->getImporter();
  if (importer.is_null()) onColumns.assign(du);
  else onColumns.doImport(du, *importer, Tpetra::INSERT);
  auto uc = onColumns.getData();
  const double S = contact_.activeSet().scale;
  const int nS = contact_.numConstraints();
  const int rank = contact_.comm()->getRank();
  std::vector<double> mine(nS, 0.0), all(nS, 0.0);
  for (const Node& n : nodes_) {
    if (n.rows.empty()) continue;
    const size_t dim = n.dofs.size(), m = n.constraints.size();
    std::vector<double> z(dim, 0.0), y(m, 0.0);
    for (size_t a = 0; a < dim; ++a) {
      z[a] = n.r[a];
      for (const auto& [c, w] : n.wRows[a]) z[a] += w * uc[c];
    }
    std::vector<double> qz(m, 0.0);  // dlambda = (Q^T V)^-1 Q^T z
    for (size_t j = 0; j < m; ++j)
      for (size_t a = 0; a < dim; ++a) qz[j] += n.Q[j * dim + a] * z[a];
    for (size_t i = 0; i < m; ++i) {
      for (size_t j = 0; j < m; ++j) y[i] += n.QtVinv[j * m + i] * qz[j];
      mine[n.constraints[i]] = y[i] / S;
    }
  }
  for (int s = 0; s < nS; ++s)  // an inactive node's pressure returns to 0
    if (!contact_.status()[s] && contact_.constraints()[s].owner == rank) mine[s] = -contact_.activeSet().rowResidual(s, 0.0) / S;
  Teuchos::reduceAll<int, double>(*contact_.comm(), Teuchos::REDUCE_SUM, nS, mine.data(), all.data());
  contact_.activeSet().applyCorrection(all);
}

}  // namespace choc
