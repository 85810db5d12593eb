// Which actions a woven tree needs as skills: read from the file (and its includes) with pugixml,
// the declared ones from <TreeNodesModel> with their ports, the used ones with the attributes they
// are given (BehaviorTree.CPP 4 refuses an attribute that is not a declared port). pugixml, not
// tinyxml2: BehaviorTree.CPP exports the symbols of its own tinyxml2 copy, which would clash.
#include "nodes.hpp"
#include "tree_actions.hpp"
#include "miron_btcpp/miron_btcpp.hpp"

#include <pugixml.hpp>

#include <filesystem>
#include <map>
#include <memory>
#include <vector>

namespace miron::btcpp
{

namespace
{

const std::set<std::string> GENERIC_TAGS = { "Action", "Condition", "Control", "Decorator", "SubTree",
                                             "SubTreePlus", "BehaviorTree", "TreeNodesModel", "include",
                                             "root" };

bool isSpecialAttribute(const std::string& name)
{
  return name == "ID" || name == "name" || (!name.empty() && name[0] == '_');
}

class Scanner
{
public:
  explicit Scanner(const BT::BehaviorTreeFactory& factory) : factory_(factory) {}

  void scanFile(const std::filesystem::path& file)
  {
    auto canonical = std::filesystem::weakly_canonical(file);
    if(!visited_.insert(canonical.string()).second)
    {
      return;
    }
    auto doc = std::make_unique<pugi::xml_document>();
    auto loaded = doc->load_file(canonical.string().c_str());
    if(!loaded)
    {
      throw BT::RuntimeError("miron-btcpp: cannot read " + file.string() + ": " + loaded.description());
    }
    auto root = doc->document_element();
    for(auto e : root.children("BehaviorTree"))
    {
      if(auto id = e.attribute("ID"))
      {
        trees_.insert(id.value());
      }
      bodies_.push_back(e);
    }
    for(auto e : root.children("include"))
    {
      if(auto path = e.attribute("path"))
      {
        scanFile(canonical.parent_path() / path.value());
      }
    }
    for(auto model : root.children("TreeNodesModel"))
    {
      for(auto action : model.children("Action"))
      {
        if(auto id = action.attribute("ID"))
        {
          auto& ports = actions_[id.value()];
          collectPorts(action, "input_port", ports.inputs);
          collectPorts(action, "output_port", ports.outputs);
          collectPorts(action, "inout_port", ports.inouts);
        }
      }
    }
    docs_.push_back(std::move(doc));
    // the used actions are collected once every tree ID is known (a tree ID used as a tag is a SubTree)
  }

  std::map<std::string, ActionPorts> actions()
  {
    for(auto body : bodies_)
    {
      for(auto child : body.children())
      {
        if(child.type() == pugi::node_element)
        {
          collectUses(child);
        }
      }
    }
    return actions_;
  }

private:
  static void collectPorts(pugi::xml_node action, const char* tag, std::set<std::string>& into)
  {
    for(auto port : action.children(tag))
    {
      if(auto name = port.attribute("name"))
      {
        into.insert(name.value());
      }
    }
  }

  void collectUses(pugi::xml_node e)
  {
    std::string tag = e.name();
    std::string id;
    if(tag == "Action" && e.attribute("ID"))
    {
      id = e.attribute("ID").value();
    }
    else if(!GENERIC_TAGS.count(tag) && !trees_.count(tag) && !e.find_child([](pugi::xml_node n) { return n.type() == pugi::node_element; }) &&
            factory_.manifests().count(tag) == 0)
    {
      id = tag;  // the compact form <MoveTo x="1"/>
    }
    if(!id.empty() && factory_.manifests().count(id) == 0)
    {
      auto& ports = actions_[id];
      for(auto a : e.attributes())
      {
        std::string name = a.name();
        if(!isSpecialAttribute(name) && !ports.outputs.count(name) && !ports.inouts.count(name))
        {
          ports.inputs.insert(name);
        }
      }
    }
    for(auto child : e.children())
    {
      if(child.type() == pugi::node_element)
      {
        collectUses(child);
      }
    }
  }

  const BT::BehaviorTreeFactory& factory_;
  std::set<std::string> visited_;
  std::set<std::string> trees_;
  std::vector<std::unique_ptr<pugi::xml_document>> docs_;
  std::vector<pugi::xml_node> bodies_;
  std::map<std::string, ActionPorts> actions_;
};
}  // namespace

std::map<std::string, ActionPorts> actionsOf(const BT::BehaviorTreeFactory& factory, const std::string& tree_file)
{
  Scanner scanner(factory);
  scanner.scanFile(tree_file);
  return scanner.actions();
}

// Ports are typed std::string, what the XML holds: an entry a remapping creates from an untyped
// port makes BehaviorTree.CPP 4.8.2's SetBlackboard write an empty value into it (it cannot parse
// the literal for an untyped entry), and throw the second time (the entry became BT::Any).
BT::TreeNodeManifest manifestOf(const std::string& id, const ActionPorts& ports)
{
  BT::TreeNodeManifest manifest;
  manifest.type = BT::NodeType::ACTION;
  manifest.registration_ID = id;
  for(const auto& p : ports.inputs)
  {
    if(!ports.outputs.count(p) && !ports.inouts.count(p))
    {
      manifest.ports.insert(BT::InputPort<std::string>(p));
    }
  }
  for(const auto& p : ports.outputs)
  {
    manifest.ports.insert(BT::OutputPort<std::string>(p));
  }
  for(const auto& p : ports.inouts)
  {
    manifest.ports.insert(BT::BidirectionalPort<std::string>(p));
  }
  return manifest;
}

std::set<std::string> registerSkillActions(BT::BehaviorTreeFactory& factory, const std::string& tree_file)
{
  std::set<std::string> registered;
  for(const auto& [id, ports] : actionsOf(factory, tree_file))
  {
    if(factory.manifests().count(id) != 0)
    {
      continue;  // the user's own node, or VariantAction
    }
    auto manifest = manifestOf(id, ports);
    std::set<std::string> outputs = ports.outputs;
    factory.registerBuilder(manifest, [id, outputs](const std::string& name, const BT::NodeConfig& config) {
      return std::make_unique<SkillAction>(name, config, id, outputs);
    });
    registered.insert(id);
  }
  return registered;
}

}  // namespace miron::btcpp
