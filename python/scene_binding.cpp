// sqdem.Scene: a validated scene, from a file, from text or from a dictionary (as its JSON text,
// json_value.hpp: the library's reader checks it with the file's messages, no line numbers).

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "json_value.hpp"
#include "sqdem/scene/scene_loader.hpp"

namespace py = pybind11;

namespace sqdem::python {

void bindScene(py::module_& m) {
  py::register_exception<SceneError>(m, "SceneError", PyExc_ValueError);
  py::class_<Scene>(m, "Scene", "A validated scene (docs/scene_reference.md for its keys and units).")
      .def_static("load", &loadScene, py::arg("path"), "Reads and validates a scene file (YAML).")
      .def_static(
          "from_text",
          [](const std::string& text, const std::string& name, const std::string& directory) {
            return sceneFromText(text, SceneOrigin{name, directory});
          },
          py::arg("text"), py::arg("name") = "scene", py::arg("directory") = ".",
          "Validates a scene given as YAML or JSON text; `name` names it in messages and files, relative paths "
          "(shape, particle, mesh files) are relative to `directory`.")
      .def_static(
          "from_dict",
          [](const py::dict& document, const std::string& name, const std::string& directory) {
            return sceneFromText(toJson(document, name).dump(), SceneOrigin{name, directory});
          },
          py::arg("document"), py::arg("name") = "scene", py::arg("directory") = ".",
          "Validates a scene given as a dictionary with the scene file's keys (the same checks and messages).")
      .def_property_readonly("name", [](const Scene& s) { return s.path; })
      .def_property_readonly("stages", [](const Scene& s) {
        std::vector<std::string> names;
        for (const StageSpec& stage : s.stages) names.push_back(stage.name);
        return names;
      }, "The stages' names, in order.")
      .def_property_readonly("materials", [](const Scene& s) {
        std::vector<std::string> names;
        for (const NamedMaterial& material : s.materials) names.push_back(material.name);
        return names;
      }, "The materials' names (a particle's `material` indexes them).")
      .def("__repr__", [](const Scene& s) {
        return "<sqdem.Scene '" + s.path + "': " + std::to_string(s.stages.size()) + " stage(s)>";
      });
}

}  // namespace sqdem::python
