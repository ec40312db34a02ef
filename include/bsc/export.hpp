#pragma once
// bsc exports: a chart as a diagram or as a document for other tools.
//
//   bsc::to_mermaid(chart)   Mermaid stateDiagram-v2
//   bsc::to_dot(chart)       Graphviz DOT
//   bsc::to_plantuml(chart)  PlantUML state diagram
//   bsc::to_scxml(chart)     W3C SCXML
//
// Not included by <bsc/bsc.hpp>: the exports build std::string, which machines never need.
// Guards and actions appear by name when they have one (bsc::named, <bsc/dsl/named.hpp>).

#include <bsc/dsl/named.hpp>
#include <bsc/export/dot.hpp>
#include <bsc/export/mermaid.hpp>
#include <bsc/export/plantuml.hpp>
#include <bsc/export/scxml.hpp>
