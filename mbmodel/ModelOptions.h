#pragma once
// What a model is built with besides the car and the track: speed, track entry, the
// track's motion, the attribution switches and the wheel–rail settings. Simbody-free, so the scenario loader
// and everything that only reads scenarios does not include Simbody.
#include "contacts/WheelRailLaws.h"
#include "mbmodel/TrackInput.h"

namespace rockroll {

/// Where the track perturbation starts relative to the car.
enum class TrackEntry {
    Lead,          ///< the leading wheelset enters at t = 0; the rear truck later (real track)
    Synchronized,  ///< every truck's leading wheelset enters at t = 0 (same phase at both trucks)
};

/// Switches for attributing a difference between formulations (scenario table
/// [attribution]); not for ordinary runs. They act on the wheelsets and their
/// side frames (the Simbody wheelset bodies), never on the bolster or car body.
struct AttributionSwitches {
    /// false: gravity off the wheelsets and side frames, their masses kept
    /// (Force::Gravity with those bodies excluded); the static wheel load falls by
    /// their weight.
    bool unsprungGravity = true;
    /// Multiplies the wheelset bodies' masses and roll inertias; the weight lost
    /// is put back by a constant downward force at each body's mass center, so the
    /// static loads do not change. Element laws (dampings) keep the true masses.
    double unsprungMassScale = 1;
    bool isDefault() const { return unsprungGravity && unsprungMassScale == 1; }
};

/// The full car's car body (scenario table [car_body]; docs/model.md, "Car-body torsion").
struct CarBodySettings {
    /// false: one rigid body (the report's); true: two rigid halves joined on the car's
    /// longitudinal axis by the car's torsional spring and damper.
    bool torsion = false;
};

struct ModelOptions {
    double speed = 0;                     ///< [m/s]
    TrackEntry entry = TrackEntry::Lead;
    TrackMotion motion;                   ///< s(t); its speed is set from `speed` when left 0
    AttributionSwitches attribution;      ///< default: none
    WheelRailSettings wheelRail;          ///< scenario [wheel_rail]
    CarBodySettings carBody;              ///< scenario [car_body] (full car)
};

}  // namespace rockroll
