// J2 plasticity (J2Plasticity.hpp: linear hardening, a flow curve or Johnson-Cook, with
// Johnson-Cook's damage) as a material point. Its state is J2Plasticity's (kJ2StateSize numbers
// per point); it reports the stress, energy and fields its state recorded at the last accepted
// step: VON_MISES, EQ_PLASTIC_STRAIN, PRESSURE (-tr sigma / 3), with a temperature TEMPERATURE,
// with damage DAMAGE.
#pragma once
#include <memory>

#include "materials/J2Plasticity.hpp"
#include "materials/MaterialPoint.hpp"

namespace choc {

std::shared_ptr<const MaterialPoint> j2Point(std::shared_ptr<const J2Plasticity> law);

}  // namespace choc
