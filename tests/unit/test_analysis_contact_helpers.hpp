// Helpers of the contact/transient analysis tests: generated two-bar scenes written to a
// temporary directory, an input deck around them, and a Model built as `choc run` does.
#pragma once
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_Core.hpp>

#include "steel_bars_xml.hpp"
#include "analysis/AnalysisRegistry.hpp"
#include "physics/Model.hpp"
#include "physics/ModelInput.hpp"
#include "input/Validation.hpp"
#include "input/XmlInput.hpp"
#include "mesh/BarImpactMesh.hpp"
#include "mesh/ExodusMeshWriter.hpp"
#include "output/HistoryCsv.hpp"

namespace choc::test {

inline std::string scratchDir(const std::string& name) {
  const std::string d = std::string(CHOC_BINARY_DIR) + "/test-scratch/" + name;
  std::filesystem::create_directories(d);
  return d;
}

// A scene: bars along z, section 0.02 x 0.02, `across1` x `across1` and `across2` x `across2`
// elements across. Written once per name (rank 0), everybody waits.
inline std::string writeScene(const std::string& dir, double length1, int along1, int across1,
                              double length2, int along2, int across2, double gap,
                              const Teuchos::RCP<const Comm>& comm) {
  BarImpactOptions o;
  o.dimension = 3;
  o.axis = 'z';
  o.length1 = length1;
  o.length2 = length2;
  o.along1 = along1;
  o.along2 = along2;
  o.across1 = across1;
  o.across2 = across2;
  o.gap = gap;
  const std::string path = dir + "/scene.exo";
  if (comm->getRank() == 0) writeExodusMesh(generateBarImpactMesh(o), path);
  comm->barrier();
  return path;
}

// The model part of an input deck (nu = 0.3, lateral motion fixed, `dirichlet` = node set
// clamped in DZ) followed by `analyses` (XML of the Analyses sublists).
inline std::string deck(const std::string& mesh, const std::string& dirichlet,
                        const std::string& analyses) {
  std::ostringstream x;
  x << R"(<ParameterList name="test">
  <Parameter name="Title" type="string" value="contact test"/>
  <ParameterList name="Mesh"><Parameter name="File" type="string" value=")" << mesh << R"("/></ParameterList>
  <ParameterList name="Model">
    <Parameter name="Active Components" type="string" value="DZ"/>
)" << test::steelBarsMaterialAndBlocksXml() << R"(    <ParameterList name="Dirichlet"><ParameterList name="clamp">
      <Parameter name="Node Set" type="string" value=")" << dirichlet << R"("/>
      <Parameter name="Components" type="string" value="DZ"/>
    </ParameterList></ParameterList>
  </ParameterList>
  <ParameterList name="Analyses">
)" << analyses << R"(
  </ParameterList>
</ParameterList>
)";
  return x.str();
}

// An analysis for a deck read only for its model (a test that builds the model, not a run).
inline const char* const kModelOnlyAnalysis =
    "<ParameterList name=\"t\"><Parameter name=\"Type\" type=\"string\" value=\"Transient\"/>"
    "<Parameter name=\"Time Step\" type=\"double\" value=\"1e-6\"/>"
    "<Parameter name=\"End Time\" type=\"double\" value=\"1e-6\"/></ParameterList>";

struct Deck {
  std::string file;
  Teuchos::RCP<Teuchos::ParameterList> input;
};

inline Deck readDeck(const std::string& dir, const std::string& text,
                     const Teuchos::RCP<const Comm>& comm) {
  Deck d;
  d.file = dir + "/input.xml";
  if (comm->getRank() == 0) std::ofstream(d.file) << text;
  comm->barrier();
  d.input = readXmlParameters(d.file);
  validate(*d.input, topLevelParameters(), InputLocation{d.file, ""});
  validateAnalyses(d.input->sublist("Analyses"), d.file);
  return d;
}

// SDNL111 C's second run (full HHT, Lagrange contact) to 4e-4 s, without output files
// other than the history and without checks, on `mesh` (the input's own when empty).
inline HistoryTable runSdnl111cC2(const std::string& dir, const std::string& mesh,
                                  const Teuchos::RCP<const Comm>& comm) {
  std::filesystem::create_directories(dir);
  const std::string file = std::string(CHOC_SOURCE_DIR) + "/input/sdnl111c.xml";
  auto input = readXmlParameters(file);
  if (!mesh.empty()) input->sublist("Mesh").set("File", mesh);
  validate(*input, topLevelParameters(), InputLocation{file, ""});
  auto& an = input->sublist("Analyses");
  an.remove("c1_modified");
  an.sublist("c2_hht").set("End Time", 4e-4);
  an.sublist("c2_hht").set("Exodus Interval", 0);
  an.sublist("c2_hht").remove("Checks");  // the document's rows and the exact solution
  validateAnalyses(an, file);
  Model model(*input, file, comm);
  auto analyses = createAnalyses(an, file);
  setupAnalyses(analyses, model);
  RunContext ctx{model, dir, {}, {}};
  analyses[0]->run(ctx);
  comm->barrier();
  return readHistoryCsv(dir + "/c2_hht.history.csv");
}

}  // namespace choc::test
