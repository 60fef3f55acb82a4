#include "pneumachaos/model/supply_line.hpp"

namespace pneumachaos {

SupplyLine::SupplyLine(const SupplyLineParams& p, const ValveLaw& valve, const GasConstants& gas,
                       double supply_Pa, double T_K)
    : regulator_(valve, gas, p.regulator_S_m2, T_K),
      supply_Pa_(supply_Pa),
      volume_m3_(p.volume_m3),
      gain_(p.polytropic_exponent * gas.R_J_per_kgK * T_K / p.volume_m3) {}

}  // namespace pneumachaos
