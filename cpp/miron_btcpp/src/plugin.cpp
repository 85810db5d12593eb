// The plugin's entry point (BT_REGISTER_NODES) and its public API (miron_btcpp.hpp).
#include "miron_btcpp/miron_btcpp.hpp"
#include "nodes.hpp"
#include "runtime.hpp"

#include <cstdlib>
#include <iostream>
#include <sstream>

BT_REGISTER_NODES(factory)
{
  factory.registerNodeType<miron::btcpp::VariantAction>("VariantAction");
  // MIRON_BTCPP_TREES=a.ext.xml:b.ext.xml also registers those trees' actions as skills, so that a
  // program which only loads plugins (e.g. from a parameter list) needs no MIRoN code at all
  if(const char* trees = std::getenv("MIRON_BTCPP_TREES"))
  {
    std::stringstream list(trees);
    std::string file;
    while(std::getline(list, file, ':'))
    {
      if(!file.empty())
      {
        miron::btcpp::registerSkillActions(factory, file);
      }
    }
  }
}

namespace miron::btcpp
{

void configure(const Endpoints& endpoints)
{
  Runtime::instance().configure(endpoints);
}

void feedBlackboard(BT::Tree& tree)
{
  if(auto root = tree.rootBlackboard())
  {
    Runtime::instance().decisions().applyTo(*root);
  }
}

std::set<std::string> followedVarpoints(const BT::Tree& tree)
{
  std::set<std::string> varpoints;
  for(const auto& subtree : tree.subtrees)
  {
    for(const auto& node : subtree->nodes)
    {
      if(auto* variant = dynamic_cast<const VariantAction*>(node.get()))
      {
        varpoints.insert(variant->varpoint());
      }
    }
  }
  return varpoints;
}

bool awaitDecisions(const std::set<std::string>& varpoints, std::chrono::milliseconds timeout)
{
  auto& decisions = Runtime::instance().decisions();
  return decisions.waitFor(
      [&] {
        for(const auto& vp : varpoints)
        {
          if(!decisions.hasVariant(vp))
          {
            return false;
          }
        }
        return true;
      },
      timeout);
}

void connectBus()
{
  Runtime::instance().bus();
}

void setVariant(const std::string& varpoint, const std::string& value)
{
  Runtime::instance().decisions().setVariant(varpoint, value);
}

Counters counters()
{
  return Runtime::instance().counters();
}

void shutdown(std::chrono::milliseconds wait)
{
  Runtime::instance().shutdown(wait);
}

}  // namespace miron::btcpp
