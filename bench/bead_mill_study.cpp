// The tables and plot data of docs/bead_mill.md (run by
// scripts/bead_mill_study.sh, never as a test: it reports run times):
//   convergence_<rotor>.csv  error of the FlexibleRotor chain against the
//                            beam oracle vs segment count, with run times;
//   span_<rotor>.csv         d, deflections and critical speeds over L_p.
// Usage: study_bead_mill OUTDIR

#include "driver/ModelSpec.h"
#include "validation/cases/BeadMillCases.h"
#include "validation/oracles/BeadMillOracle.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>

using namespace milldyn;

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: study_bead_mill OUTDIR\n";
        return 2;
    }
    const std::string dir = argv[1];
    for (int which = 0; which < 2; ++which) {
        const std::string tag = beadmill::rotorTag(which);
        {
            std::ofstream out(dir + "/convergence_" + tag + ".csv");
            out << "segments_requested,segments,seal_error,end_error,omega_error,static_seconds,linearize_seconds\n";
            ModelSpec base = beadmill::readRotor(which);
            const ElementSpec& e0 = beadmill::rotorElement(base);
            const oracles::BeadMillBeam beam(beadmill::oracleShaft(e0));
            const double g = beadmill::gravityOf(base);
            const double seal = beam.calcGravityDeflection(beam.shaft().span + e0.number("seal_offset"), g);
            const double end = beam.calcGravityDeflection(beam.getLength(), g);
            const double omega = beam.calcFiniteElementFrequencies(400, true, true).at(0);
            for (int n : {4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192}) {
                ModelSpec spec = base;
                beadmill::rotorElement(spec).params["segments"].number = n;
                const auto st = beadmill::runStatic(spec);
                const auto fb = beadmill::firstBending(spec);
                out << n << "," << st.segments << "," << std::abs(st.seal - seal) / seal << ","
                    << std::abs(st.end - end) / end << "," << std::abs(fb.omega - omega) / omega << ","
                    << st.seconds << "," << fb.seconds << "\n";
                std::cerr << tag << " n=" << n << " done\n";
            }
        }
        {
            std::ofstream out(dir + "/span_" + tag + ".csv");
            out << "span_m,d_mm,seal_um,seal_oracle_um,end_um,end_oracle_um,omega_cr,omega_fe,omega_rayleigh,"
                   "omega_dunkerley,omega_fe_rigid_bearings,run_over_cr\n";
            for (double span : {0.15, 0.2, 0.267, 0.3, 0.383, 0.5}) {
                ModelSpec spec = beadmill::readRotor(which);
                ElementSpec& e = beadmill::rotorElement(spec);
                e.params["span"].number = span;
                oracles::BeadMillShaft shaft = beadmill::oracleShaft(e);
                const oracles::BeadMillBeam beam(shaft);
                shaft.stiffnessA = shaft.stiffnessB = std::numeric_limits<double>::infinity();
                const oracles::BeadMillBeam rigid(shaft);
                const double g = beadmill::gravityOf(spec);
                const auto st = beadmill::runStatic(spec);
                const auto fb = beadmill::firstBending(spec);
                out << span << "," << beam.shaft().diameter * 1e3 << "," << st.seal * 1e6 << ","
                    << beam.calcGravityDeflection(span + e.number("seal_offset"), g) * 1e6 << "," << st.end * 1e6
                    << "," << beam.calcGravityDeflection(beam.getLength(), g) * 1e6 << "," << fb.omega << ","
                    << beam.calcFiniteElementFrequencies(400, true, true).at(0) << ","
                    << beam.calcRayleighCriticalSpeed(true) << "," << beam.calcDunkerleyCriticalSpeed() << ","
                    << rigid.calcFiniteElementFrequencies(400, true, true).at(0) << ","
                    << beadmill::runningSpeed(e) / fb.omega << "\n";
                std::cerr << tag << " L_p=" << span << " done\n";
            }
        }
    }
    return 0;
}
