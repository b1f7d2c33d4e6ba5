#include "urdf_mutator.hpp"

#include <sstream>

namespace flexmbd {
namespace fuzz {
namespace {

using tinyxml2::XMLAttribute;
using tinyxml2::XMLDocument;
using tinyxml2::XMLElement;

// urdfdom's joint types, and one it does not know.
const std::vector<std::string> kJointTypes = {"revolute", "continuous", "prismatic", "fixed",
                                              "floating", "planar",     "spherical", "hinge"};

// Every element under `doc`, in document order; iterative so a deep document cannot overflow.
std::vector<XMLElement*> CollectElements(XMLDocument* doc) {
  std::vector<XMLElement*> elements;
  std::vector<XMLElement*> pending;
  if (doc->RootElement() != nullptr) pending.push_back(doc->RootElement());
  while (!pending.empty()) {
    XMLElement* element = pending.back();
    pending.pop_back();
    elements.push_back(element);
    for (XMLElement* child = element->FirstChildElement(); child; child = child->NextSiblingElement()) {
      pending.push_back(child);
    }
  }
  return elements;
}

std::vector<XMLElement*> Named(const std::vector<XMLElement*>& elements, const std::string& tag) {
  std::vector<XMLElement*> found;
  for (XMLElement* element : elements) {
    if (tag == element->Name()) found.push_back(element);
  }
  return found;
}

std::vector<std::string> Tokens(const std::string& text) {
  std::istringstream stream(text);
  std::vector<std::string> tokens;
  for (std::string token; stream >> token;) tokens.push_back(token);
  return tokens;
}

std::string Joined(const std::vector<std::string>& tokens) {
  std::string text;
  for (const std::string& token : tokens) text += (text.empty() ? "" : " ") + token;
  return text;
}

const XMLAttribute* PickAttribute(const XMLElement* element, Rng* rng) {
  std::vector<const XMLAttribute*> attributes;
  for (const XMLAttribute* a = element->FirstAttribute(); a; a = a->Next()) attributes.push_back(a);
  return attributes.empty() ? nullptr : attributes[Pick(rng, attributes.size())];
}

// One entry of a number list ("0 0 1") replaced, dropped or doubled.
void MutateNumbers(XMLElement* element, Rng* rng) {
  const XMLAttribute* attribute = PickAttribute(element, rng);
  if (attribute == nullptr) return;
  std::vector<std::string> tokens = Tokens(attribute->Value());
  if (tokens.empty()) tokens.push_back("0");
  const size_t index = Pick(rng, tokens.size());
  switch (Pick(rng, 5)) {
    case 0:
      tokens.erase(tokens.begin() + static_cast<long>(index));
      break;
    case 1:
      tokens.push_back(tokens[index]);
      break;
    default:
      tokens[index] = HostileNumber(tokens[index], rng);
      break;
  }
  element->SetAttribute(attribute->Name(), Joined(tokens).c_str());
}

// A link reference of a joint (<parent link>, <child link>) pointed at another link or at none.
void Rewire(const std::vector<XMLElement*>& elements, Rng* rng) {
  std::vector<XMLElement*> ends = Named(elements, "parent");
  const std::vector<XMLElement*> children = Named(elements, "child");
  ends.insert(ends.end(), children.begin(), children.end());
  const std::vector<XMLElement*> links = Named(elements, "link");
  if (ends.empty()) return;
  const char* name = links.empty() || Chance(rng, 0.2) ? nullptr : links[Pick(rng, links.size())]->Attribute("name");
  ends[Pick(rng, ends.size())]->SetAttribute("link", name ? name : "no_such_link");
}

void Rename(const std::vector<XMLElement*>& elements, Rng* rng) {
  const std::vector<std::string> names = {"", "a,b", "line\nbreak", "world", "base_link", "dup"};
  std::vector<XMLElement*> named;
  for (XMLElement* element : elements) {
    if (element->Attribute("name")) named.push_back(element);
  }
  if (named.empty()) return;
  const char* other = named[Pick(rng, named.size())]->Attribute("name");
  const std::string name = Chance(rng, 0.5) ? std::string(other) : names[Pick(rng, names.size())];
  named[Pick(rng, named.size())]->SetAttribute("name", name.c_str());
}

}  // namespace

UrdfMutator::UrdfMutator(const std::vector<std::string>& donors) {
  for (const std::string& text : donors) {
    auto doc = std::make_unique<XMLDocument>();
    if (doc->Parse(text.c_str(), text.size()) == tinyxml2::XML_SUCCESS && doc->RootElement()) {
      donors_.push_back(std::move(doc));
    }
  }
}

void UrdfMutator::Mutate(XMLDocument* doc, Rng* rng) const {
  const std::vector<XMLElement*> elements = CollectElements(doc);
  if (elements.empty()) return;
  XMLElement* element = elements[Pick(rng, elements.size())];
  switch (Pick(rng, 9)) {
    case 0:
    case 1:
      MutateNumbers(element, rng);
      return;
    case 2: {
      const std::vector<XMLElement*> joints = Named(elements, "joint");
      if (!joints.empty()) {
        joints[Pick(rng, joints.size())]->SetAttribute("type", kJointTypes[Pick(rng, kJointTypes.size())].c_str());
      }
      return;
    }
    case 3:
      Rewire(elements, rng);
      return;
    case 4:
      if (element != doc->RootElement()) doc->DeleteNode(element);
      return;
    case 5:
      if (element != doc->RootElement()) element->Parent()->InsertAfterChild(element, element->DeepClone(doc));
      return;
    case 6:
      Rename(elements, rng);
      return;
    case 7:
      if (const XMLAttribute* attribute = PickAttribute(element, rng)) element->DeleteAttribute(attribute->Name());
      return;
    default: {  // a donor's link or joint added to this robot
      if (donors_.empty()) return;
      XMLDocument* donor = donors_[Pick(rng, donors_.size())].get();
      const std::vector<XMLElement*> parts = Named(CollectElements(donor), Chance(rng, 0.5) ? "link" : "joint");
      if (!parts.empty()) doc->RootElement()->InsertEndChild(parts[Pick(rng, parts.size())]->DeepClone(doc));
      return;
    }
  }
}

std::string PrintXml(const XMLDocument& doc) {
  tinyxml2::XMLPrinter printer;
  doc.Print(&printer);
  return printer.CStr();
}

}  // namespace fuzz
}  // namespace flexmbd
