#include "LiveHeads.h"

#include <mrolr/geometry/Frames.h>
#include <mrolr/sim/SceneBuilder.h>
#include <mrolr/sim/SimHead.h>
#include <mrolr/sim/StereoRenderer.h>

#include <opencv2/imgproc.hpp>

#include <stdexcept>

namespace mrolr::apps
{
namespace
{
class SyntheticLiveHead : public LiveHead
{
 public:
	SyntheticLiveHead(const world::World& w, const geometry::BiSightHead& head, int texture_px,
	                  double noise, unsigned seed)
	    : world_(head, landmarks(w, texture_px), noise, seed)
	{
	}
	void setVehicle(const Eigen::Vector3d& x) override { world_.setVehicle(x); }
	bool rendersSurfaces() const override { return false; }
	void moveTo(const geometry::HeadAngles& a) override { world_.moveTo(a); }
	geometry::HeadAngles angles() const override { return world_.angles(); }
	vision::StereoImages grab() override { return world_.grab(); }

 private:
	static std::vector<vision::TexturedLandmark> landmarks(const world::World& w, int px)
	{
		std::vector<vision::TexturedLandmark> out;
		for (size_t i = 0; i < w.landmarks.size(); ++i)
			out.push_back(
			    {w.landmarks[i].name, w.landmarks[i].p_LinW, vision::makeTexture(px, 1000 + i)});
		return out;
	}
	vision::SyntheticWorld world_;
};

/** sim::SimHead (hw::HeadDevice) rendering the lab, seen through vision::StereoHeadDevice. */
class LabLiveHead : public LiveHead
{
 public:
	LabLiveHead(const world::World& w, const geometry::BiSightHead& head, double noise,
	            unsigned seed)
	    : head_height_m_(head.options().head_height_m),
	      renderer_(head, renderOptions(noise, seed)),
	      lab_(sim::buildLabScene(w)),
	      sim_head_(renderer_, *lab_.scene,
	                [this] { return geometry::T_C0inW(x_, head_height_m_); }, {})
	{
	}
	void setVehicle(const Eigen::Vector3d& x) override { x_ = x; }
	bool rendersSurfaces() const override { return true; }
	void moveTo(const geometry::HeadAngles& a) override { sim_head_.moveTo(a); }
	geometry::HeadAngles angles() const override { return sim_head_.angles(); }
	vision::StereoImages grab() override
	{
		const hw::StereoImages im = sim_head_.grab();
		return {toGray(im.left), toGray(im.right), im.angles};
	}

 private:
	static sim::RenderOptions renderOptions(double noise, unsigned seed)
	{
		sim::RenderOptions o;
		o.noise_sigma_grey = noise, o.seed = seed;
		return o;
	}
	double head_height_m_;
	Eigen::Vector3d x_ = Eigen::Vector3d::Zero();
	sim::StereoRenderer renderer_;
	sim::LabScene lab_;
	sim::SimHead sim_head_;
};
}  // namespace

cv::Mat toGray(const mrpt::img::CImage& img)
{
	cv::Mat m = img.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY), g;
	if (m.channels() == 1) return m.clone();
	cv::cvtColor(m, g, cv::COLOR_BGR2GRAY);
	return g;
}

std::unique_ptr<LiveHead> makeLiveHead(const std::string& kind, const world::World& w,
                                       const geometry::BiSightHead& head, int texture_px,
                                       double noise_grey, unsigned seed)
{
	if (kind == "synthetic")
		return std::make_unique<SyntheticLiveHead>(w, head, texture_px, noise_grey, seed);
	if (kind == "lab") return std::make_unique<LabLiveHead>(w, head, noise_grey, seed);
	throw std::invalid_argument("unknown head '" + kind + "' (expected synthetic or lab)");
}

}  // namespace mrolr::apps
