// The model part shared by the unit tests that build SDNL111's two bars (blocks POU1 and POU2)
// in an input: the steel material (E = 2e11 Pa, nu = 0.3, rho = 7800 kg/m3) and both blocks of
// it, as the lines inside 'Model'.
#pragma once

namespace choc {
namespace test {

inline const char* steelBarsMaterialAndBlocksXml() {
  return R"(    <ParameterList name="Materials"><ParameterList name="steel">
      <Parameter name="Young's Modulus" type="double" value="2e11"/>
      <Parameter name="Poisson's Ratio" type="double" value="0.3"/>
      <Parameter name="Density" type="double" value="7800"/>
    </ParameterList></ParameterList>
    <ParameterList name="Blocks">
      <ParameterList name="POU1"><Parameter name="Material" type="string" value="steel"/></ParameterList>
      <ParameterList name="POU2"><Parameter name="Material" type="string" value="steel"/></ParameterList>
    </ParameterList>
)";
}

}  // namespace test
}  // namespace choc
