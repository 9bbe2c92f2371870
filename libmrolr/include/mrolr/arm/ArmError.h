#pragma once
/** Errors of the arm area. Each message names the limit or the input that was wrong. */

#include <stdexcept>

namespace mrolr::arm
{
/** A pose the arm cannot reach, or joint values outside a limit; what() names the limit. */
class UnreachableError : public std::runtime_error
{
 public:
	using std::runtime_error::runtime_error;
};

/** Malformed geometric input (a 3×4 pose whose rotation is not a rotation, ...). */
class PoseInputError : public std::invalid_argument
{
 public:
	using std::invalid_argument::invalid_argument;
};

}  // namespace mrolr::arm
