// Map management of ActiveSlamFilter: reset (5.31), known features (5.6.2), initialisation
// (5.46–5.48), deletion (5.49), world-frame zeroing (5.50–5.52), the attempt record (5.7), and
// read access to x and P.
#include <mrolr/slam/ActiveSlamFilter.h>

#include <stdexcept>

namespace mrolr::slam
{
namespace
{
void checkIndex(size_t i, size_t n, const char* what)
{
	if (i >= n)
		throw std::out_of_range(std::string(what) + ": feature " + std::to_string(i) + " of " +
		                        std::to_string(n));
}

/** x and P with rows/columns [o, o+3) removed. */
void removeBlock(Eigen::VectorXd& x, Eigen::MatrixXd& P, Eigen::Index o)
{
	const Eigen::Index n = x.size(), t = n - o - 3;
	Eigen::VectorXd xn(n - 3);
	xn << x.head(o), x.tail(t);
	Eigen::MatrixXd Pn(n - 3, n - 3);
	Pn << P.topLeftCorner(o, o), P.topRightCorner(o, t), P.bottomLeftCorner(t, o),
	    P.bottomRightCorner(t, t);
	x = xn;
	P = Pn;
}
}  // namespace

void ActiveSlamFilter::reset(const Eigen::Vector3d& x_v)
{
	tracker_ = PostponedTracker33{};
	info_.clear();
	setState(x_v, Eigen::Matrix3d::Zero());
	notePrediction(x_v);
}

void ActiveSlamFilter::setState(const Eigen::VectorXd& x, const Eigen::MatrixXd& P)
{
	const auto n = static_cast<Eigen::Index>(3 + 3 * info_.size());
	if (x.size() != n || P.rows() != n || P.cols() != n)
		throw std::invalid_argument("ActiveSlamFilter::setState: size does not match the map");
	tracker_ = PostponedTracker33{};
	m_xkk.resize(n);
	m_pkk.setSize(n, n);
	m_xkk.asEigen() = x;
	m_pkk.asEigen() = P;
}

void ActiveSlamFilter::appendFeature(const Eigen::Vector3d& y, const Eigen::MatrixXd& P_new,
                                     FeatureInfo info)
{
	// P_new: the 3 new rows (3 × (n + 3)), the last block being P_yy.
	const Eigen::VectorXd x = stateVector();
	const Eigen::MatrixXd P = covariance();
	const Eigen::Index n = x.size();
	Eigen::VectorXd xn(n + 3);
	xn << x, y;
	Eigen::MatrixXd Pn(n + 3, n + 3);
	Pn.topLeftCorner(n, n) = P;
	Pn.bottomRows(3) = P_new;
	Pn.topRightCorner(n, 3) = P_new.leftCols(n).transpose();
	info_.push_back(std::move(info));
	setState(xn, Pn);
}

size_t ActiveSlamFilter::addKnownFeature(const std::string& label, const Eigen::Vector3d& p_FinW)
{
	return addKnownFeature(label, p_FinW, Eigen::Matrix3d::Zero());
}

size_t ActiveSlamFilter::addKnownFeature(const std::string& label, const Eigen::Vector3d& p_FinW,
                                         const Eigen::Matrix3d& P_FF,
                                         const std::optional<Eigen::Vector3d>& p_viewinW)
{
	synchronise();
	FeatureInfo info;
	info.label = label;
	info.known = true;
	info.p_FinW_first = p_FinW;
	info.p_C0atInitInW =
	    p_viewinW ? *p_viewinW : headCentreInW(vehicleRaw(), options_.head.constants);
	Eigen::MatrixXd rows = Eigen::MatrixXd::Zero(3, m_xkk.size() + 3);
	rows.rightCols(3) = 0.5 * (P_FF + P_FF.transpose());
	appendFeature(p_FinW, rows, std::move(info));
	return info_.size() - 1;
}

size_t ActiveSlamFilter::initialiseFeature(const std::string& label, const Eigen::Vector3d& h)
{
	synchronise();
	const Eigen::Vector3d xv = vehicleRaw();
	const auto g = initialiseFromMeasurement(xv, h, options_.head.constants);
	const Eigen::MatrixXd P = covariance();
	const Eigen::Index n = P.rows();
	// Eq 5.48: P_yx = G_x P_xx, P_yyj = G_x P_xyj, P_yy = G_x P_xx G_xᵀ + G_h R G_hᵀ.
	Eigen::MatrixXd rows(3, n + 3);
	rows.leftCols(n) = g.dy_dxv * P.topRows(3);
	rows.rightCols(3) = g.dy_dxv * P.topLeftCorner(3, 3) * g.dy_dxv.transpose() +
	                    g.dy_dh * measurementNoise() * g.dy_dh.transpose();
	FeatureInfo info;
	info.label = label;
	info.p_C0atInitInW = headCentreInW(xv, options_.head.constants);
	info.p_FinW_first = g.p_FinW;
	appendFeature(g.p_FinW, rows, std::move(info));
	return info_.size() - 1;
}

void ActiveSlamFilter::deleteFeature(size_t i)
{
	checkIndex(i, info_.size(), "deleteFeature");
	Eigen::VectorXd x = stateVector();
	Eigen::MatrixXd P = covariance();
	removeBlock(x, P, static_cast<Eigen::Index>(3 + 3 * i));
	info_.erase(info_.begin() + static_cast<long>(i));
	setState(x, P);
}

void ActiveSlamFilter::zeroWorldFrame()
{
	// Eqs 5.50–5.52: x_v ← 0, y_i ← m_Gi + M_h (the feature in the frame of the current base),
	// P ← J P Jᵀ with ∂y_new/∂x_v = ∂m/∂x_v, ∂y_new/∂y_i = R_y(φ)ᵀ and a zero vehicle row.
	Eigen::VectorXd x = stateVector();
	const Eigen::MatrixXd P = covariance();
	const Eigen::Vector3d xv = x.head<3>();
	const auto& head = options_.head.constants;
	Eigen::MatrixXd J = Eigen::MatrixXd::Zero(x.size(), x.size());
	for (size_t i = 0; i < info_.size(); ++i)
	{
		const Eigen::Index o = static_cast<Eigen::Index>(3 + 3 * i);
		const auto Jm = pointInHeadJacobians(xv, x.segment<3>(o), head);
		J.block<3, 3>(o, 0) = Jm.dm_dxv;
		J.block<3, 3>(o, o) = Jm.dm_dy;
		x.segment<3>(o) =
		    pointInHead(xv, x.segment<3>(o), head) + Eigen::Vector3d(0, head.head_height_m, 0);
		info_[i].p_C0atInitInW = pointInHead(xv, info_[i].p_C0atInitInW, head) +
		                          Eigen::Vector3d(0, head.head_height_m, 0);
		info_[i].p_FinW_first = x.segment<3>(o);  // FEJ restarts in the new frame
	}
	x.head<3>().setZero();
	setState(x, J * P * J.transpose());
	notePrediction(x.head<3>());
}

void ActiveSlamFilter::recordAttempt(size_t i, bool success)
{
	checkIndex(i, info_.size(), "recordAttempt");
	auto& info = info_[i];
	info.attempts.push_back(success);
	while (static_cast<int>(info.attempts.size()) > options_.attempt_window)
		info.attempts.pop_front();
	(success ? info.successes : info.failures)++;
}

bool ActiveSlamFilter::shouldDelete(size_t i) const
{
	checkIndex(i, info_.size(), "shouldDelete");
	const auto& a = info_[i].attempts;
	int failed = 0;
	for (bool ok : a) failed += ok ? 0 : 1;
	return 2 * failed > options_.attempt_window;
}

size_t ActiveSlamFilter::numFeatures()
{
	return info_.size();
}

Eigen::Vector3d ActiveSlamFilter::vehicle()
{
	if (tracker_.tracking()) return tracker_.vehicle();
	return vehicleRaw();
}

Eigen::Matrix3d ActiveSlamFilter::vehicleCovariance()
{
	if (tracker_.tracking()) return tracker_.activeCovariance().topLeftCorner<3, 3>();
	return m_pkk.asEigen().topLeftCorner<3, 3>();
}

Eigen::Vector3d ActiveSlamFilter::feature(size_t i)
{
	checkIndex(i, info_.size(), "feature");
	if (tracker_.tracking() && tracker_.trackedFeature() == i) return tracker_.feature();
	synchronise();
	return featureRaw(i);
}

Eigen::Matrix3d ActiveSlamFilter::featureCovariance(size_t i)
{
	checkIndex(i, info_.size(), "featureCovariance");
	if (tracker_.tracking() && tracker_.trackedFeature() == i)
		return tracker_.activeCovariance().bottomRightCorner<3, 3>();
	synchronise();
	const auto o = static_cast<Eigen::Index>(3 + 3 * i);
	return m_pkk.asEigen().block<3, 3>(o, o);
}

Eigen::VectorXd ActiveSlamFilter::stateVector()
{
	synchronise();
	return m_xkk.asEigen();
}

Eigen::MatrixXd ActiveSlamFilter::covariance()
{
	synchronise();
	return m_pkk.asEigen();
}

Eigen::Vector3d ActiveSlamFilter::predictedMeasurement(size_t i)
{
	return predictMeasurement(vehicle(), feature(i), options_.head.constants);
}

Eigen::Matrix3d ActiveSlamFilter::innovationCovariance(size_t i)
{
	checkIndex(i, info_.size(), "innovationCovariance");
	const Eigen::Vector3d xv = vehicle(), y = feature(i);
	const auto J = measurementJacobians(xv, y, options_.head.constants);
	const auto o = static_cast<Eigen::Index>(3 + 3 * i);
	const auto P = m_pkk.asEigen();  // synchronised by feature(i) unless i is the tracked one
	Eigen::Matrix<double, 3, 6> H;
	H << J.H_xv, J.H_y;
	Eigen::Matrix<double, 6, 6> Pa;
	if (tracker_.tracking() && tracker_.trackedFeature() == i)
		Pa = tracker_.activeCovariance();
	else
		Pa << P.topLeftCorner<3, 3>(), P.block<3, 3>(0, o), P.block<3, 3>(o, 0),
		    P.block<3, 3>(o, o);
	return H * Pa * H.transpose() + measurementNoise();
}

Eigen::MatrixXd ActiveSlamFilter::jointInnovationCovariance(const std::vector<size_t>& features)
{
	synchronise();
	const Eigen::Vector3d xv = vehicle();
	const auto P = m_pkk.asEigen();
	const auto n = static_cast<Eigen::Index>(features.size());
	Eigen::MatrixXd H = Eigen::MatrixXd::Zero(3 * n, P.cols());
	for (Eigen::Index k = 0; k < n; ++k)
	{
		const size_t i = features[static_cast<size_t>(k)];
		checkIndex(i, info_.size(), "jointInnovationCovariance");
		const auto J = measurementJacobians(xv, feature(i), options_.head.constants);
		H.block<3, 3>(3 * k, 0) = J.H_xv;
		H.block<3, 3>(3 * k, static_cast<Eigen::Index>(3 + 3 * i)) = J.H_y;
	}
	Eigen::MatrixXd S = H * P * H.transpose();
	for (Eigen::Index k = 0; k < n; ++k) S.block<3, 3>(3 * k, 3 * k) += measurementNoise();
	return S;
}

void ActiveSlamFilter::inflateVehicleCovariance(const Eigen::Matrix3d& Q)
{
	synchronise();
	Eigen::MatrixXd P = covariance();
	P.topLeftCorner<3, 3>() += 0.5 * (Q + Q.transpose());
	setState(stateVector(), P);
}

}  // namespace mrolr::slam
