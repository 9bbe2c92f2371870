#include <mrolr/sim/SimBase.h>
#include <mrolr/util/OptionsBinder.h>

#include <cmath>
#include <ostream>
#include <stdexcept>

namespace mrolr::sim
{
namespace
{
using O = SimBaseOptions;
constexpr auto kOpt = util::Presence::Optional;

const util::OptionsBinder<O>& simBaseOptionsBinder()
{
	static const auto b = util::OptionsBinder<O>()
	    .number("ticks_per_m", &O::ticks_per_m, 1, 1e7, kOpt)
	    .number("slip_probability", &O::slip_probability, 0, 1, kOpt)
	    .integer("slip_burst_steps", &O::slip_burst_steps, 1, 1000, kOpt)
	    .number("slip_fraction", &O::slip_fraction, 0, 1, kOpt)
	    .integer("seed", &O::seed, 0, 4294967295L, kOpt)
	    .number("footprint_length_m", [](O& o) -> double& { return o.footprint.length_m; }, 0.05,
	            5, kOpt)
	    .number("footprint_width_m", [](O& o) -> double& { return o.footprint.width_m; }, 0.05, 5,
	            kOpt)
	    .number("footprint_offset_m", [](O& o) -> double& { return o.footprint.offset_m; }, -2, 2,
	            kOpt)
	    .number("kick_after_s", &O::kick_after_s, -1e12, 1e12, kOpt)
	    .number("kick_deg", &O::kick_deg, -180, 180, kOpt);
	return b;
}
}  // namespace

void SimBaseOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg,
                                        const std::string& section)
{
	simBaseOptionsBinder().load(cfg, section, *this);
}

void SimBaseOptions::dump(std::ostream& out) const
{
	simBaseOptionsBinder().dump(out, *this);
}

SimBase::SimBase(const base::LabmateModel& model, const SimBaseOptions& options,
                 const Eigen::Vector3d& start_zxphi)
    : model_(model), options_(options), rng_(options.seed), true_(start_zxphi)
{
	odo_.xv_zxphi = start_zxphi;
}

void SimBase::setCollisionWorld(std::shared_ptr<const CollisionWorld> world)
{
	if (world)
		if (const auto t = world->touchAt(true_))
			throw std::invalid_argument("SimBase: the base at (z, x) = (" +
			                            std::to_string(true_[0]) + ", " + std::to_string(true_[1]) +
			                            ") m already overlaps " + t->what);
	collisions_ = std::move(world);
	odo_.bumper = collisions_ && collisions_->touchAt(true_, kBumperTravel_m);
}

base::WheelControl SimBase::turnedWheels(const base::WheelControl& u)
{
	// the motors do not hold the commanded speed exactly (eq 5.13); the encoders see this
	std::normal_distribution<double> n(0, 1);
	const Eigen::Matrix2d U = model_.controlCovariance(u);
	base::WheelControl t = u;
	t.v1_mps += std::sqrt(U(0, 0)) * n(rng_);
	t.v2_mps += std::sqrt(U(1, 1)) * n(rng_);
	return t;
}

base::WheelControl SimBase::slipped(const base::WheelControl& turned)
{
	base::WheelControl m = turned;
	if (slip_left_ == 0 &&
	    std::uniform_real_distribution<double>(0, 1)(rng_) < options_.slip_probability)
		slip_left_ = options_.slip_burst_steps;
	if (slip_left_ > 0)
	{
		m.v2_mps *= 1 - options_.slip_fraction;  // the left wheel spins without gripping
		--slip_left_;
		++slip_steps_total_;
	}
	return m;
}

double SimBase::moveTruth(const base::WheelControl& moved)
{
	if (!collisions_)
	{
		true_ = model_.move(true_, moved);
		return 1.0;
	}
	const Eigen::Vector3d from = true_;
	const Motion arc = [this, from, moved](double t)
	{ return model_.move(from, {moved.v1_mps, moved.v2_mps, moved.dt_s * t}); };
	const auto contact = collisions_->firstContact(arc, std::abs(model_.arcLength(moved)),
	                                               std::abs(model_.turnAngle(moved)));
	odo_.bumper = false;
	if (!contact)
	{
		true_ = model_.move(from, moved);
		// within the bumper's travel of something: pressed, and the world side notes the touch
		if (const auto touch = collisions_->touchAt(true_, kBumperTravel_m))
		{
			odo_.bumper = true;
			if (!last_contact_ || last_contact_->what != touch->what)
				last_contact_ = Contact{touch->what, touch->p_zx_m, true_, 1.0};
		}
		return 1.0;
	}
	true_ = contact->last_free_zxphi;
	last_contact_ = contact;
	++contacts_total_;
	odo_.bumper = true;
	return contact->free_fraction;
}

long SimBase::countTicks(double travel_m, double& residual)
{
	const double exact = travel_m * options_.ticks_per_m + residual;
	const long ticks = std::lround(exact);
	residual = exact - double(ticks);
	return ticks;
}

void SimBase::countEncoders(const base::WheelControl& turned, double stall_fraction)
{
	// the encoders count what the wheels turned, up to where a contact stalled them
	const double travelled_s = turned.dt_s * stall_fraction;
	const long dr = countTicks(turned.v1_mps * travelled_s, residual_right_);
	const long dl = countTicks(turned.v2_mps * travelled_s, residual_left_);
	odo_.ticks_right += dr;
	odo_.ticks_left += dl;
	if (turned.dt_s > 0)
	{
		const base::WheelControl measured{double(dr) / options_.ticks_per_m / turned.dt_s,
		                                  double(dl) / options_.ticks_per_m / turned.dt_s,
		                                  turned.dt_s};
		odo_.xv_zxphi = model_.move(odo_.xv_zxphi, measured);
	}
}

void SimBase::step(const base::WheelControl& u)
{
	const base::WheelControl turned = turnedWheels(u);
	base::WheelControl moved = slipped(turned);
	const bool turning = u.dt_s > 0 && u.v1_mps * u.v2_mps < 0;
	if (!kicked_ && options_.kick_after_s >= 0 && odo_.time_s >= options_.kick_after_s && turning)
	{  // the turn slips: the base turns by kick_deg more than its wheels (as a wheel would
		// turn the base about the other): v1 - v2 grows by 2 D1 kick / dt
		const double extra = options_.kick_deg * M_PI / 180.0 *
		                     model_.options().wheel_half_separation_m / u.dt_s;
		moved.v1_mps += extra, moved.v2_mps -= extra;
		kicked_ = true;
	}
	const double stall_fraction = moveTruth(moved);
	countEncoders(turned, stall_fraction);
	odo_.time_s += u.dt_s;
}

}  // namespace mrolr::sim
