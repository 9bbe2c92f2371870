#include "SimulationOutputs.h"

#include <fstream>
#include <iomanip>
#include <stdexcept>

namespace mrolr::apps::detail
{
namespace
{
std::ofstream openOut(const std::string& path)
{
	std::ofstream f(path);
	if (!f) throw std::runtime_error("cannot write '" + path + "'");
	f << std::setprecision(12);
	return f;
}

void writeVec(std::ostream& f, const Eigen::Vector3d& v)
{
	f << "," << v[0] << "," << v[1] << "," << v[2];
}
}  // namespace

void writeCsv(const std::string& dir, const std::vector<eval::RunResult>& runs,
              const eval::MonteCarloSummary& summary)
{
	auto f = openOut(dir + "/steps.csv");
	f << "run,step,true_z_m,true_x_m,true_phi_rad,est_z_m,est_x_m,est_phi_rad,var_z_m2,var_x_m2,"
	     "var_phi_rad2,nees,dr_z_m,dr_x_m,dr_phi_rad,features,measured\n";
	for (size_t r = 0; r < runs.size(); ++r)
		for (size_t k = 0; k < runs[r].steps.size(); ++k)
		{
			const auto& s = runs[r].steps[k];
			f << r << "," << k;
			writeVec(f, s.truth);
			writeVec(f, s.estimate);
			writeVec(f, s.P_vv.diagonal());
			f << "," << s.nees;
			writeVec(f, s.dead_reckoning);
			f << "," << s.features << "," << s.measured << "\n";
		}
	auto n = openOut(dir + "/nees.csv");
	n << "step,mean_nees,lo,hi\n";
	for (size_t k = 0; k < summary.mean_nees.size(); ++k)
		n << k << "," << summary.mean_nees[k] << "," << summary.nees_lo << "," << summary.nees_hi
		  << "\n";
}

}  // namespace mrolr::apps::detail
