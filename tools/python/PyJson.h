#pragma once
// JSON (nlohmann, as the run report and `info` make it) as Python objects: objects become
// dicts in the same key order, arrays lists, numbers int or float, null None.
#include <pybind11/pybind11.h>

#include <nlohmann/json.hpp>

namespace aniso::python {

pybind11::object toPython(const nlohmann::ordered_json& j);

}  // namespace aniso::python
