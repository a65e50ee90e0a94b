// libFuzzer target: the BehaviorTree.CPP XML importer and schema writer on
// arbitrary bytes. Every input either builds a tree or throws rtamp::Error; a
// tree that builds exports, and the export imports back to the same XML.
#include <cstddef>
#include <cstdint>
#include <string>

#include "rtamp/bt/bt.hpp"
#include "rtamp/bt/xml_import.hpp"
#include "rtamp/bt/xml_schema.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  rtamp::bt::NodeRegistry leaves;
  leaves.add_action("Act", rtamp::bt::Action::Callbacks{[](rtamp::bt::Node&) { return rtamp::bt::Status::Success; },
                                                        {}, {}});
  leaves.add_condition("Cond", [](rtamp::bt::Node&) { return true; });
  try {
    (void)rtamp::bt::btcpp_xsd_for(text);
  } catch (const rtamp::Error&) {
  }
  try {
    rtamp::bt::Tree tree;
    tree.set_root(rtamp::bt::from_btcpp_xml(text, leaves));
    const std::string xml = rtamp::bt::to_btcpp_xml(tree);
    rtamp::bt::Tree again;
    again.set_root(rtamp::bt::from_btcpp_xml(xml, leaves));
    if (rtamp::bt::to_btcpp_xml(again) != xml) __builtin_trap();
  } catch (const rtamp::Error&) {
  }
  return 0;
}
