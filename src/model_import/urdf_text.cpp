// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "model_import/urdf_text.hpp"

#include <cmath>
#include <cstdlib>
#include <memory>

#include <libxml/parser.h>
#include <libxml/tree.h>

#include "model_import/imported_arm.hpp"

namespace armstudy::model_import {
namespace {
struct DocDeleter {
  void operator()(xmlDoc* d) const { xmlFreeDoc(d); }
};
using Doc = std::unique_ptr<xmlDoc, DocDeleter>;

// no network, no external entities, no DTD loading: the file's own bytes only
Doc parse(const std::string& bytes) {
  return Doc(xmlReadMemory(bytes.data(), static_cast<int>(bytes.size()), "model.xml", nullptr,
                           XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING));
}

bool named(const xmlNode* n, const char* name) {
  return n->type == XML_ELEMENT_NODE && xmlStrcmp(n->name, BAD_CAST name) == 0;
}

std::optional<std::string> attribute(xmlNode* n, const char* name) {
  xmlChar* v = xmlGetProp(n, BAD_CAST name);
  if (!v) return std::nullopt;
  std::string s(reinterpret_cast<const char*>(v));
  xmlFree(v);
  return s;
}

// a limit attribute: a finite number >= 0, or absent
std::optional<double> limit_value(const std::string& path, const std::string& joint, xmlNode* limit,
                                  const char* name) {
  const auto text = attribute(limit, name);
  if (!text) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(text->c_str(), &end);
  if (end == text->c_str() || *end != '\0' || !std::isfinite(v) || v < 0)
    throw ImportError(path + ": joint '" + joint + "' has <limit " + name + "=\"" + *text +
                      "\">; expected a number >= 0");
  return v;
}

xmlNode* child(xmlNode* parent, const char* name) {
  for (xmlNode* c = parent->children; c; c = c->next)
    if (named(c, name)) return c;
  return nullptr;
}
}  // namespace

bool is_urdf(const std::string& bytes) {
  const Doc doc = parse(bytes);
  if (!doc) return false;
  const xmlNode* root = xmlDocGetRootElement(doc.get());
  return root && named(root, "robot");
}

UrdfText read_urdf(const std::string& path, const std::string& bytes) {
  const Doc doc = parse(bytes);
  xmlNode* root = doc ? xmlDocGetRootElement(doc.get()) : nullptr;
  if (!root || !named(root, "robot"))
    throw ImportError(path + ": not a URDF (no <robot> root element); expected a URDF or MJCF");
  UrdfText out;
  for (xmlNode* j = root->children; j; j = j->next) {
    if (!named(j, "joint")) continue;
    const std::string name = attribute(j, "name").value_or("");
    if (xmlNode* limit = child(j, "limit"))
      out.limits[name] = {limit_value(path, name, limit, "effort"),
                          limit_value(path, name, limit, "velocity")};
  }
  // fixed links stay bodies: the tip's frame is then the model's, not lost in its parent
  xmlNode* mj = child(root, "mujoco");
  if (!mj) mj = xmlNewChild(root, nullptr, BAD_CAST "mujoco", nullptr);
  xmlNode* compiler = child(mj, "compiler");
  if (!compiler) compiler = xmlNewChild(mj, nullptr, BAD_CAST "compiler", nullptr);
  xmlSetProp(compiler, BAD_CAST "fusestatic", BAD_CAST "false");
  xmlChar* text = nullptr;
  int size = 0;
  xmlDocDumpMemory(doc.get(), &text, &size);
  if (!text) throw ImportError(path + ": could not write the URDF for MuJoCo");
  out.for_mujoco.assign(reinterpret_cast<const char*>(text), static_cast<size_t>(size));
  xmlFree(text);
  return out;
}

}  // namespace armstudy::model_import
