#include "plugins/scene/MobilizerReactions.h"

namespace milldyn {

using namespace SimTK;

void MobilizerReactions::realizeTopology(State& s) const {
    m_entry = m_matter.allocateLazyCacheEntry(s, Stage::Acceleration, new Value<Vector_<SpatialVec>>());
}

const Vector_<SpatialVec>& MobilizerReactions::get(const State& s) const {
    auto& value = Value<Vector_<SpatialVec>>::updDowncast(m_matter.updCacheEntry(s, m_entry));
    if (!m_matter.isCacheValueRealized(s, m_entry)) {
        m_matter.calcMobilizerReactionForces(s, value);
        m_matter.markCacheValueRealized(s, m_entry);
    }
    return value;
}

}  // namespace milldyn
