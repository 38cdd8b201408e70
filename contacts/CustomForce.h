#pragma once
// Adding a custom force element to a Simbody system. Simbody's Force::Custom takes
// ownership of a raw Implementation pointer; this is the one place rockroll hands
// it over, so no model code writes a naked `new`.
#include <Simbody.h>

#include <memory>
#include <utility>

namespace rockroll {

/// Constructs `Element` from `args`, adds it to `forces` (which then owns it) and
/// returns it, valid for the life of the System.
template <class Element, class... Args>
const Element& addCustomForce(SimTK::GeneralForceSubsystem& forces, Args&&... args) {
    auto element = std::make_unique<Element>(std::forward<Args>(args)...);
    const Element& added = *element;
    SimTK::Force::Custom(forces, element.release());
    return added;
}

}  // namespace rockroll
