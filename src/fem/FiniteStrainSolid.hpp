// Isoparametric continuum elements in finite strain, total Lagrangian: every integral over
// the reference configuration X, the deformation gradient F = I + du/dX at each quadrature
// point, C = F^T F given to a hyperelastic material (materials/Hyperelastic.hpp) for the
// second Piola-Kirchhoff stress S, and
//
//   internal force  f_ai = int P_iJ dN_a/dX_J dV,                 P = F S (first Piola-Kirchhoff)
//   tangent         K_ai,bk = int dN_a/dX_J A_iJkL dN_b/dX_L dV,   A_iJkL = delta_ik S_JL
//                                                                         + F_iI F_kK CC_IJKL
//
// (material plus geometric stiffness), with the quadrature and node checks of the small-strain
// kernel (SolidElement.hpp). Plane strain: F_zz = 1, the in-plane F only. Axisymmetric
// (x = R, y = Z): F_thetatheta = 1 + u_r / R, whose variation N_a / R adds to the radial
// rows, integrals over the full ring. Element DOFs node-major like every kernel.
//
// The material is a material point (materials/MaterialPoint.hpp): it gives P and dP/dF from F
// and, for a law with state (J2 plasticity), each quadrature point's committed state
// (stateSize() numbers per point, in the caller's arrays: old in, new out); a small-strain law
// (finiteStrain() false) gives P = sigma(sym(F - I)) and A = dsigma/deps, the same integrals
// being the small-strain element (no geometric stiffness, no det F check).
//
// F-bar (de Souza Neto, Peric, Dutko and Owen 1996) in its mean-dilatation form, for every
// element with more than one point (not TET4, TRI3) in finite strain: each point's material sees
// Fbar = (Jbar / J)^(1/3) F, Jbar = int J dV / V the element's volume ratio (its current volume
// over its reference volume), so the volume change is the element's mean alone, one constraint
// per element (Q1/P0 for HEX8 and QUAD4, P2/P0 for TET10 and TRI6), and isochoric (plastic,
// nearly incompressible) flow does not lock; the force is the exact derivative of int W(Fbar) dV. The mean
// (rather than det F at the centre) keeps the patch test on distorted and axisymmetric elements:
// under a homogeneous F, Fbar = F and the force is the standard element's. Its tangent is the
// consistent one (FBarTangent.hpp: dense in the element, symmetric where the material tangent is) for
// Newton; with `elasticTangent` (the explicit critical step) it is the standard element's at Fbar.
//
// One point with hourglass control (Flanagan and Belytschko 1981, in total Lagrangian form), for
// HEX8 in 3D and QUAD4 in plane strain: the material is called once, at the element's mean
// deformation gradient F = I + sum_a u_a (x) b_a, with b_a = int dN_a/dX dV / V the mean
// reference gradient (exact for every linear field, so the patch test holds on distorted
// elements), f_a = V P b_a. One point leaves the element's hourglass modes without stiffness;
// each mode m (the bilinear and trilinear products of the natural coordinates: eta zeta, zeta xi,
// xi eta, xi eta zeta in 3D, xi eta in 2D) gets its vector gamma_m,a = Gamma_m,a - (Gamma_m .
// X_J) b_a,J, which is orthogonal to every linear field (translations, rigid rotations of any
// size, homogeneous deformations), and the energy 1/2 k sum_m |q_m|^2 with q_m,i = sum_a
// gamma_m,a u_a,i: objective, conservative (it is part of the element's energy and so of the
// balance), its force k gamma_m,a q_m,i and its constant tangent k gamma_m,a gamma_m,b delta_ik.
// k = Q (lambda + 2 mu) V (b : b) / 72 in 3D (/ 24 in plane strain, per unit thickness): with Q = 1
// the xi eta mode of a cube gets the normal-stress energy the fully integrated element gives it.
// The single point is also the element's only pressure point: it does not lock (Q1/P0's count).
#pragma once
#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem/DenseMatrix.hpp"
#include "fem/Kinematics.hpp"
#include "fem/ShapeFunctions.hpp"
#include "materials/Hyperelastic.hpp"
#include "materials/J2Plasticity.hpp"
#include "materials/MaterialPoint.hpp"

namespace choc {

// det F <= 0 (or a material that cannot take C) at a quadrature point: the message names the
// natural point and the value; the caller adds the element, the block and the time.
class InvertedElement : public std::domain_error {
 public:
  using std::domain_error::domain_error;
};

// The reference geometry of one element at its quadrature points, computed once (the total
// Lagrangian integrals never change): per point q the weight w_q dV_q, dN_a/dX_J (J < 3, zero
// beyond the parametric dimension) and, axisymmetric, N_a and the radius R.
struct ElementGeometry {
  int points = 0, nodes = 0;
  std::vector<double> weight;  // [q]
  std::vector<double> dNdX;    // [(q nodes + a) 3 + J]
  std::vector<double> N;       // [q nodes + a], axisymmetric only
  std::vector<double> radius;  // [q], axisymmetric only
  // One point with hourglass control: gamma_m,a ([m nodes + a]) and the stiffness k (header).
  std::vector<double> hourglass;
  double hourglassStiffness = 0.0;
};

// How an element is integrated: the full rule, F-bar on it, or one point with hourglass control
// of coefficient `hourglass` (Q above).
struct ElementFormulation {
  bool fbar = false;
  bool onePoint = false;
  double hourglass = 0.0;
};

struct PointView;
struct PointState;
class FBarTangent;

class FiniteStrainSolid {
 public:
  // Throws std::invalid_argument for an unknown topology or one that does not fit the
  // kinematics.
  FiniteStrainSolid(const std::string& topology, Kinematics kinematics,
                    std::shared_ptr<const HyperelasticMaterial> material, bool fbar = false);
  FiniteStrainSolid(const std::string& topology, Kinematics kinematics, std::shared_ptr<const J2Plasticity> material,
                    bool fbar = false);
  // Any formulation; throws std::invalid_argument where it does not apply (F-bar on one-point
  // elements or in small strain, one point on other than HEX8 in 3D and QUAD4 in plane strain).
  FiniteStrainSolid(const std::string& topology, Kinematics kinematics,
                    std::shared_ptr<const MaterialPoint> material, const ElementFormulation& formulation);
  bool fbar() const { return fbar_; }
  bool onePoint() const { return onePoint_; }
  // The integration rule of the element's points (its state has one per point).
  const QuadratureRule& rule() const { return *rule_; }
  int numNodes() const { return nodeCount(shape_); }
  SolidShape shape() const { return shape_; }
  Kinematics kinematics() const { return kin_; }
  int componentsPerNode() const { return kin_ == Kinematics::ThreeD ? 3 : 2; }
  const MaterialPoint& material() const { return *material_; }
  // A dissipative material (a return map: J2 plasticity).
  bool plastic() const { return material_->dissipative(); }
  // A material whose points carry a temperature (Johnson-Cook).
  bool thermal() const { return material_->hasTemperature(); }
  // A material that accumulates damage, and its largest point value in a state.
  bool damaged() const { return material_->hasDamage(); }
  double largestDamage(const double* state) const;
  // The points of a state at the melting temperature (0 without temperature).
  int pointsAtMelting(const double* state) const;
  // Finite-strain kinematics (the material's: every hyperelastic kernel, a plastic one in finite strain).
  bool finiteKinematics() const { return material_->finiteStrain(); }
  // The numbers of state an element keeps (0 for a stateless material), and their virgin values.
  int stateSize() const;
  void initialState(double* state) const;
  // The material's modulus at C = I, dS_11/dE_11 = lambda + 2 mu: the size of the stress's terms
  // per unit of strain.
  double modulus() const;

  // The element's reference geometry; throws std::invalid_argument like the small-strain
  // kernel (inverted or degenerate reference element, axisymmetric radii).
  ElementGeometry geometry(const std::vector<Point3>& X) const;
  // f (resized to numNodes() * componentsPerNode()) at the nodal displacements u (same
  // order); K = df/du when K is not null. Returns the element's strain energy int W dV.
  // Throws InvertedElement (det F <= 0). A plastic material reads the committed state `old`
  // (stateSize() numbers) and, when given, writes the new one to `next` and adds the
  // increment's dissipated work (J2Response::plasticWork) times dV to *plasticWork. With
  // `elasticTangent`, K takes a plastic material's elastic tangent (the explicit critical step).
  // dt: the increment's duration (a rate-dependent flow stress; 0: quasi-static). One point:
  // the hourglass part of the returned energy into *hourglassEnergy when given.
  double evaluate(const ElementGeometry& g, const std::vector<double>& u, std::vector<double>& f, DenseMatrix* K,
                  const double* old = nullptr, double* next = nullptr, double* plasticWork = nullptr,
                  bool elasticTangent = false, double dt = 0.0, double* hourglassEnergy = nullptr) const;
  double evaluate(const std::vector<Point3>& X, const std::vector<double>& u, std::vector<double>& f,
                  DenseMatrix* K) const {
    return evaluate(geometry(X), u, f, K);
  }

  // One point: the element's hourglass energy 1/2 k sum_m |q_m|^2 at u (0 for other formulations).
  double hourglassEnergy(const ElementGeometry& g, const std::vector<double>& u) const;

  // The Cauchy stress (xx, yy, zz, xy, yz, zx; for axisymmetric rr, zz, thetatheta, rz, 0, 0)
  // and the strain-energy density W, both averaged over the element's reference volume.
  // A material that reports its state: the stress and energy its state `old` records (those of
  // the last accepted increment: the state ends at u). With `fields`, the averages of the
  // material's named fields (MaterialPoint::fieldNames, in that order).
  void averageStress(const ElementGeometry& g, const std::vector<double>& u, std::array<double, 6>& sigma,
                     double& energyDensity, const double* old = nullptr, std::vector<double>* fields = nullptr) const;
  void averageStress(const std::vector<Point3>& X, const std::vector<double>& u, std::array<double, 6>& sigma,
                     double& energyDensity) const {
    averageStress(geometry(X), u, sigma, energyDensity);
  }

 private:
  SolidShape shape_;
  Kinematics kin_;
  std::shared_ptr<const MaterialPoint> material_;
  size_t fields_ = 0;  // the material's named fields (fieldNames(), asked once)
  bool fbar_ = false;
  bool onePoint_ = false;
  double hourglass_ = 0.0;
  const QuadratureRule* rule_ = nullptr;  // the static rule of the formulation (one point or the full rule)
  void checkFormulation() const;
  // One point: the element's mean gradient and hourglass vectors from the full rule's geometry.
  void condenseToOnePoint(const std::vector<Point3>& X, ElementGeometry& g) const;
  // One point: the hourglass force into f and stiffness into K (when not null); returns its energy.
  double addHourglass(const ElementGeometry& g, const std::vector<double>& u, std::vector<double>& f,
                      DenseMatrix* K) const;
  // F-bar: Jbar and B = d ln Jbar / du (element DOFs) from each point's F (F[q]), with each
  // point's F^-1 into Finv; 0 without F-bar. Throws InvertedElement.
  double meanDilatation(const ElementGeometry& g, const std::vector<Mat3>& F, std::vector<double>& B,
                        std::vector<Mat3>& Finv) const;
  void addFBarForce(const PointView& p, const PointState& s, const Mat3& Finv, const std::vector<double>& B,
                    double w, std::vector<double>& f) const;
  void addFBarTangent(const PointView& p, const PointState& s, const Mat3& F, const Mat3& Finv, double w,
                      FBarTangent& tangent, DenseMatrix& K) const;
};

}  // namespace choc
