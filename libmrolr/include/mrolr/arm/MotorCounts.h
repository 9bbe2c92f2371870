#pragma once
/** Motor encoder counts of the RTX to and from joint values (thesis B.3.3.1, compute_xyz).
 *   column   = (d1 − d1_top) / 0.2667 mm          shoulder = q2 / 0.03422°
 *   elbow    = q3 / 0.06844°                      yaw      = q4 / 0.10267°
 *   wrist1   = (−pitch + roll) / 0.07415°         wrist2   = (−pitch − roll) / 0.07415°
 * with pitch = 90° − q5 and roll = q6 (the differential wrist of compute_xyz). compute_xyz measures
 * the yaw count from the wrist's azimuth; here it is the DH joint q4, relative to the forearm. */

#include <mrolr/arm/RtxJoints.h>
#include <mrolr/arm/RtxOptions.h>

#include <array>
#include <string>
#include <utility>

namespace mrolr::arm
{
/** Real-valued counts indexed by Motor (round them for the controller). */
using MotorCounts = std::array<double, kMotorCount>;

/** Counts of joint values @p j (q1 is not a motor and is ignored). */
MotorCounts jointsToCounts(const RtxJoints& j, const RtxOptions& o);

/** The two differential wrist motors' counts of q5, q6 (radians), as jointsToCounts gives them. */
std::pair<double, double> wristCounts(double q5_rad, double q6_rad, const RtxOptions& o);

/** Joint values of counts @p c; q1 = o.q1_fixed_deg. */
RtxJoints countsToJoints(const MotorCounts& c, const RtxOptions& o);

/** Counts rounded to the nearest integer, as the controller takes them. */
std::array<long, kMotorCount> roundCounts(const MotorCounts& c);

/** Index of the first motor whose count is outside its limit (1e-9 count tolerance), or −1. */
int firstViolatedMotor(const MotorCounts& c, const RtxOptions& o);

/** "shoulder count 2700.3 outside limit [-2630, 2630]". */
std::string describeViolation(Motor m, double count, const CountRange& limit);

/** Empty when every count is within its limit; otherwise "shoulder count 2700.3 outside limit
 * [-2630, 2630]" for the first motor out of range (with a 1e-9 count tolerance). */
std::string limitViolation(const MotorCounts& c, const RtxOptions& o);

/** Throws UnreachableError with limitViolation() unless every count is within its limit. */
void requireWithinLimits(const RtxJoints& j, const RtxOptions& o);

}  // namespace mrolr::arm
