// acoustics/bubble/liquid_properties.h — material constants of the liquid and of the gas in a bubble.
// Defaults: water and air at 20 °C, 1 atm (docs/physics.md §2, from shared physics.md §2).
#pragma once

namespace fluidsound::acoustics {

/// Properties of the gas inside a bubble (air), for the thermal damping and polytropic index.
struct GasProperties {
  double thermalConductivity = 0.02587;  ///< K_g [W/(m·K)], air at 20 °C
  double specificHeat = 1005.0;          ///< c_p,g [J/(kg·K)], air at constant pressure
  double molarMass = 0.028965;           ///< M [kg/mol], dry air
  double temperature = 293.15;           ///< T [K]
  double heatCapacityRatio = 1.4;        ///< γ [-], air (diatomic ideal gas)
};

/// Universal gas constant R_gas [J/(mol·K)] (CODATA 2018, exact).
inline constexpr double kGasConstant = 8.314462618;

/// Properties of the liquid around a bubble. Water at 20 °C by default.
struct LiquidProperties {
  double density = 998.0;             ///< ρ [kg/m³]
  double ambientPressure = 101325.0;  ///< p₀ [Pa], at the free surface
  double surfaceTension = 0.0728;     ///< σ [N/m], air–water
  double viscosity = 1.002e-3;        ///< μ [Pa·s], dynamic viscosity at 20 °C
  double soundSpeed = 1482.0;         ///< c_w [m/s], fresh water
  double vapourPressure = 2339.0;     ///< p_v [Pa], saturated vapour; used only with the vapour option
  double gravity = 9.81;              ///< g [m/s²]; used only with the hydrostatic option
  GasProperties gas;                  ///< the gas in the bubble
};

/// Properties of the air above the liquid, for the transfer of sound into air.
struct AirProperties {
  double density = 1.204;     ///< ρ_a [kg/m³], 20 °C, 1 atm
  double soundSpeed = 343.2;  ///< c_a [m/s], 20 °C
};

}  // namespace fluidsound::acoustics
