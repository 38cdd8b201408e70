#pragma once
// A value a force element computes while applying its forces (Dynamics stage)
// and reads again later in the same realization: the bristle rates it writes in
// realizeAcceleration, the dissipated power the energy meter integrates. It
// lives in the State as a cache entry (no mutable data in the element), and it
// counts as valid only at Dynamics stage or above: any change of q, u, z or
// time drops the State below Dynamics, so a stale value can never be read.
#include <Simbody.h>

#include <memory>

namespace rockroll {

template <class T>
class DynamicsCache {
public:
    /// Call from the element's realizeTopology.
    void allocate(const SimTK::Subsystem& subsystem, SimTK::State& s) const {
        // Simbody takes ownership of the cache value.
        index_ = subsystem.allocateCacheEntry(s, SimTK::Stage::Dynamics, std::make_unique<SimTK::Value<T>>().release());
    }
    /// Written by calcForce, while the subsystem is being realized to Dynamics.
    T& upd(const SimTK::Subsystem& subsystem, const SimTK::State& s) const {
        return SimTK::Value<T>::updDowncast(subsystem.updCacheEntry(s, index_)).upd();
    }
    /// The value calcForce stored for this State, or null below Dynamics stage.
    const T* find(const SimTK::Subsystem& subsystem, const SimTK::State& s) const {
        if (subsystem.getStage(s) < SimTK::Stage::Dynamics) return nullptr;
        return &SimTK::Value<T>::downcast(subsystem.getCacheEntry(s, index_)).get();
    }

private:
    // Topology-stage index, as Simbody's own elements keep theirs.
    mutable SimTK::CacheEntryIndex index_;
};

}  // namespace rockroll
