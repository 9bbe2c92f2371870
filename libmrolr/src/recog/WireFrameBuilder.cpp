#include <mrolr/recog/WireFrameBuilder.h>

namespace mrolr::recog
{
WireFrameBuilder::WireFrameBuilder(std::string name)
{
	wf_.name = std::move(name);
}

WireFrameBuilder& WireFrameBuilder::line(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
	model::Line3 l;
	l.id = next_id_++;
	l.p1 = a;
	l.p2 = b;
	wf_.lines.push_back(l);
	return *this;
}

WireFrameBuilder& WireFrameBuilder::polyline(const std::vector<Eigen::Vector3d>& pts, bool closed)
{
	for (size_t i = 0; i + 1 < pts.size(); ++i) line(pts[i], pts[i + 1]);
	if (closed && pts.size() > 2) line(pts.back(), pts.front());
	return *this;
}

WireFrameBuilder& WireFrameBuilder::box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi)
{
	auto corner = [&](int i)
	{
		return Eigen::Vector3d(i & 1 ? hi.x() : lo.x(), i & 2 ? hi.y() : lo.y(),
		                       i & 4 ? hi.z() : lo.z());
	};
	for (int i = 0; i < 8; ++i)
		for (int bit : {1, 2, 4})
			if (!(i & bit)) line(corner(i), corner(i | bit));
	return *this;
}

WireFrameBuilder& WireFrameBuilder::arc(const Eigen::Vector3d& centre,
                                        const Eigen::Vector3d& normal, const Eigen::Vector3d& major,
                                        double r, double t1, double t2)
{
	model::Conic3 c;
	c.id = next_id_++;
	c.centre = centre;
	c.normal = normal.normalized();
	c.major = (major - major.dot(c.normal) * c.normal).normalized();
	c.a = c.b = r;
	c.t1 = t1;
	c.t2 = t2;
	wf_.conics.push_back(c);
	return *this;
}

WireFrameBuilder& WireFrameBuilder::circle(const Eigen::Vector3d& centre, double r)
{
	return arc(centre, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(), r, 0, 2 * M_PI);
}

}  // namespace mrolr::recog
