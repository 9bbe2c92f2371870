// An ambiguous recognition in the retrieval: one grasp for every rival pose, or a second look.
#include <mrolr/arm/GraspChain.h>
#include <mrolr/mission/Retrieval.h>
#include "RetrievalDetail.h"

namespace mrolr::mission
{
using detail::angleBetweenDeg;

Sighting sightingOf(const SearchResult& s)
{
	Sighting out;
	out.T_OinC0_mm = s.T_OinC0_mm;
	if (!s.recognition.ambiguous) return out;
	const Eigen::Isometry3d T_LinC0 = s.T_OinC0_mm * s.T_OinL_mm.inverse();
	for (const auto& p : s.recognition.poses) out.poses_C0_mm.push_back(T_LinC0 * p.T_OinS);
	return out;
}

const char* AmbiguityHandling::name(Resolution r)
{
	switch (r)
	{
		case Resolution::None: return "not_ambiguous";
		case Resolution::GraspFitsAll: return "grasp_fits_every_pose";
		case Resolution::LookedAgain: return "resolved_by_looking_again";
		case Resolution::StillAmbiguous: return "still_ambiguous_best_pose_taken";
	}
	return "?";
}

int Retrieval::posesGrippedAlike(const Eigen::Isometry3d& T_GinA, double turn_deg,
                                 const std::vector<Eigen::Isometry3d>& poses_C0_mm) const
{
	const double step = o_.retrieval.grasp_yaw_search_deg;
	const Eigen::Isometry3d jaws_round = T_GinA * Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ());
	int alike = 0;
	for (const auto& P : poses_C0_mm)
	{
		const Eigen::Isometry3d T_OinA = arm::objectInArm(T_C0inA_, P);
		bool same = false;
		for (int k = 0; !same && (k == 0 || (step > 0 && k * step < 360 - 1e-9)); ++k)
		{
			const Eigen::Isometry3d G = T_OinA * graspInObject(turn_deg + k * step);
			for (const auto* want : {&T_GinA, &jaws_round})
				same = same || ((G.translation() - want->translation()).norm() <= kSameGrip_mm &&
				                angleBetweenDeg(G, *want) <= kSameGrip_deg);
		}
		alike += same;
	}
	return alike;
}

void Retrieval::judgeAmbiguity(RetrievalResult& r, const Sighting& first, Timeline& timeline) const
{
	auto& a = r.ambiguity;
	if (!first.ambiguous()) return;
	a.poses = static_cast<int>(first.poses_C0_mm.size());
	a.poses_fitted = posesGrippedAlike(r.T_GinA, r.grasp_turn_deg, first.poses_C0_mm);
	const bool all = a.poses_fitted == a.poses;
	a.resolution = all ? AmbiguityHandling::Resolution::GraspFitsAll
	                   : AmbiguityHandling::Resolution::StillAmbiguous;
	timeline.note("ambiguous pose (" + std::to_string(a.poses) + " poses): " +
	              (all ? "the grasp grips every one of them alike"
	                   : std::to_string(a.poses_fitted) + " gripped alike; the verification view decides"));
}

void Retrieval::lookedAgain(RetrievalResult& r, const std::optional<Sighting>& seen,
                            Timeline& timeline) const
{
	auto& a = r.ambiguity;
	if (a.resolution != AmbiguityHandling::Resolution::StillAmbiguous) return;
	if (seen && !seen->ambiguous())
		a.resolution = AmbiguityHandling::Resolution::LookedAgain;
	else if (seen && posesGrippedAlike(r.T_GinA, r.grasp_turn_deg, seen->poses_C0_mm) ==
	                     static_cast<int>(seen->poses_C0_mm.size()))
		a.resolution = AmbiguityHandling::Resolution::GraspFitsAll;
	timeline.note(std::string("ambiguity after looking again: ") + AmbiguityHandling::name(a.resolution));
}

}  // namespace mrolr::mission
