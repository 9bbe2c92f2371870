#include <mrolr/slam/PostponedTracker.h>

namespace mrolr::slam
{
// The one instantiation MROLR's filter uses; other sizes are instantiated where they are used.
template class PostponedTracker<3, 3>;

}  // namespace mrolr::slam
