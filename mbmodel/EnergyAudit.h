#pragma once
// Energy audit of a recorded run (docs/model.md, "Energy audit"). No Simbody dependency.
//
// Every time-domain model records three cumulative channels (ChannelLayout):
//   energy_stored_J      E(t): kinetic + gravity + elastic energy of every element
//   energy_input_J       W(t): work done by the rails on the wheels since t = 0
//   energy_dissipated_J  D(t): energy dissipated since t = 0 (contact damping,
//                        viscous dampers, friction)
// and the balance W = ΔE + D must hold up to integration error.
#include "mbmodel/ChannelLayout.h"
#include "mbmodel/TimeHistory.h"

namespace rockroll {

/// |W − ΔE − D| / max(|W|, D) at the last sample, ΔE = E(last) − E(first).
/// NaN if the layout has no energy channels or nothing was exchanged (W = D = 0).
double calcEnergyBalanceError(const TimeHistory& h, const ChannelLayout& layout);

/// The largest |W − ΔE − D| / max(|W|, D) over the samples at or after tFrom
/// (early samples, where W and D are still tiny, make a noisy ratio). NaN as above.
double calcWorstEnergyBalanceError(const TimeHistory& h, const ChannelLayout& layout, double tFrom = 0);

}  // namespace rockroll
