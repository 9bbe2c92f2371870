#include <mrolr/recog/MemberCandidates.h>

#include <mrolr/recog/CliqueMatcher.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

namespace mrolr::recog
{
MemberCandidates::MemberCandidates(const ModelTable& model, const std::vector<Feature>& scene,
                                   const Tolerance& loosest)
    : model_(model), loosest_(loosest)
{
	if (scene.size() >= (std::uint32_t{1} << 30))
		throw std::invalid_argument("MemberCandidates: too many scene features");
	oriented_.reserve(2 * scene.size());
	for (const auto& f : scene) oriented_.push_back(f), oriented_.push_back(f.flipped());
}

namespace
{
/** @p levels' distinct tolerances, tightest first, or none when they are not a chain (each at
 * least as loose as the one before in both terms, by 1e-6 where it differs). */
std::vector<Tolerance> chainOf(const std::vector<LevelParams>& levels)
{
	std::vector<Tolerance> t;
	for (const auto& p : levels) t.push_back(levelTolerance(p));
	std::sort(t.begin(), t.end(),
	          [](const Tolerance& a, const Tolerance& b)
	          { return std::tie(a.beta_mm, a.theta_rad) < std::tie(b.beta_mm, b.theta_rad); });
	const auto same = [](const Tolerance& a, const Tolerance& b)
	{ return a.beta_mm == b.beta_mm && a.theta_rad == b.theta_rad; };
	t.erase(std::unique(t.begin(), t.end(), same), t.end());
	const auto apart = [](double a, double b) { return a == b || b >= a + 1e-6; };
	for (size_t k = 1; k < t.size(); ++k)
		if (!apart(t[k - 1].beta_mm, t[k].beta_mm) || !apart(t[k - 1].theta_rad, t[k].theta_rad))
			return {};
	if (t.size() > INT8_MAX) return {};
	return t;
}
}  // namespace

MemberCandidates::MemberCandidates(const ModelTable& model, const std::vector<Feature>& scene,
                                   const std::vector<LevelParams>& levels)
    : MemberCandidates(model, scene, loosestTolerance(levels))
{
	chain_ = chainOf(levels);
	if (chain_.empty()) return;
	// its last is at least as loose as every level in both terms (chainOf), as loosest_ is:
	// consistency being monotone in the tolerance, no level's pair is left out under it
	loosest_ = chain_.back();
	own_rank_ = static_cast<int>(chain_.size()) - 1;
}

int MemberCandidates::rankOf(const Tolerance& t) const
{
	for (size_t k = 0; k < chain_.size(); ++k)
		if (chain_[k].beta_mm == t.beta_mm && chain_[k].theta_rad == t.theta_rad)
			return static_cast<int>(k);
	return -1;
}

MemberCandidates::List& MemberCandidates::of(size_t focus, size_t member, size_t focus_scene,
                                             bool focus_flipped)
{
	const size_t n = model_.features().size();
	const size_t o_focus = 2 * focus_scene + (focus_flipped ? 1 : 0);
	if (pair_slot_.empty()) pair_slot_.assign(n * n, -1);
	std::int32_t& slot = pair_slot_[focus * n + member];
	if (slot < 0)
		slot = static_cast<std::int32_t>(by_pair_.size()),
		by_pair_.emplace_back(oriented_.size(), -1);
	std::int32_t& index = by_pair_[static_cast<size_t>(slot)][o_focus];
	if (index >= 0) return lists_[static_cast<size_t>(index)];
	index = static_cast<std::int32_t>(lists_.size());
	static thread_local std::vector<std::uint32_t> list;  // then copied at its size: one allocation
	list.clear();
	const auto& mf = model_.features();
	const auto& rel = model_.relation(focus, member);
	const Feature& sa = oriented_[o_focus];
	// consistent()'s first tests on the packed features at once: most pairs fail them
	const Gated& gated = gatedFor(member);
	mayBeConsistent(rel, mf[focus], mf[member], sa, gated.packed, loosest_, keep_);
	const CosineRange angle = cosineRange(rel, loosest_);
	for (size_t k = 0; k < gated.index.size(); ++k)
	{
		const size_t o = gated.index[k];
		if (keep_[k] && consistent(rel, angle, mf[focus], mf[member], sa, oriented_[o], loosest_))
			list.push_back(static_cast<std::uint32_t>(o));
	}
	return lists_.emplace_back(List{list, {}});
}

const MemberCandidates::Gated& MemberCandidates::gatedFor(size_t member)
{
	const auto [it, fresh] = gated_.try_emplace(member);
	if (!fresh) return it->second;
	// a scene feature that fails the gate at the loosest position error fails it at every level
	// (a member's gate has no length ratio: that is the focus's)
	LevelParams loosest;
	loosest.position_error_mm = loosest_.beta_mm;
	Gated& g = it->second;
	g.index = passingUnaryGate(model_.features()[member], oriented_, loosest, false);
	for (const size_t o : g.index) g.packed.push_back(oriented_[o]);
	return g;
}

Tolerance levelTolerance(const LevelParams& p)
{
	return Tolerance(p.position_error_mm, p.rotation_deg * M_PI / 180.0);
}

Tolerance loosestTolerance(const std::vector<LevelParams>& levels)
{
	double beta_mm = 0, theta_deg = 0;
	for (const auto& p : levels)
		beta_mm = std::max(beta_mm, p.position_error_mm),
		theta_deg = std::max(theta_deg, p.rotation_deg);
	return Tolerance(beta_mm + 1e-6, theta_deg * M_PI / 180.0 + 1e-6);
}

}  // namespace mrolr::recog
