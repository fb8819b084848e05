#pragma once
/// Internal: the checks of an elastic mode's fields, shared by the planar flexible body
/// (flexible.hpp) and the 3D body's modes (body3d.hpp). Each throws InputError naming the field.
namespace freestand::dynamics::detail {

/// A fixed-base frequency: finite and > 0 Hz (field: "flexible.f", "flexible.f_x", ...).
void require_modal_frequency(double frequency_hz, const char* field);
/// The modal damping ratio in [0, 1) ("flexible.zeta").
void require_modal_damping(double damping);
/// The modal mass fraction m_s / M in (0, 1) ("flexible.mass").
void require_modal_mass_fraction(double fraction);
/// The modal mass's height above the base, finite and > 0 m ("flexible.height").
void require_modal_height(double height_m);

}  // namespace freestand::dynamics::detail
