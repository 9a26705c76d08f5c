#include "sqdem/io/paraview_script.hpp"

#include "sqdem/archive/atomic_file.hpp"

namespace sqdem {

void writeParaViewScript(const std::filesystem::path& directory, const std::string& name, ParaViewSeries series) {
  // The script holds no user text (it finds the run's name from its own file name).
  const auto flag = [](bool on) { return on ? "True" : "False"; };
  std::string text = R"(# sqdem: a view of this run's output for ParaView 5.11 (the run's name is this file's, less
# '_view.py').
#   paraview --script=<name>_view.py           opens it in the GUI
#   pvbatch <name>_view.py --png picture.png   renders the last frame to a PNG
import os
import sys

from paraview.simple import *

here, script = os.path.split(os.path.abspath(__file__))
NAME = script[:-len('_view.py')]
SURFACES, CONTACTS, WALLS, BONDS = @SURFACES, @CONTACTS, @WALLS, @BONDS


def series(kind):
    return PVDReader(registrationName=kind, FileName=os.path.join(here, NAME + '_' + kind + '.pvd'))


view = GetActiveViewOrCreate('RenderView')
view.OrientationAxesVisibility = 1
particles = series('surfaces' if SURFACES else 'particles')
shown = Show(particles, view)
if not SURFACES:
    shown.SetRepresentationType('Points')
    shown.PointSize = 4
ColorBy(shown, ('POINTS', 'coordination'))
shown.LookupTable = GetColorTransferFunction('coordination')
shown.LookupTable.ApplyPreset('Viridis (matplotlib)', True)
shown.SetScalarBarVisibility(view, True)
if WALLS:
    walls = Show(series('walls'), view)
    ColorBy(walls, None)
    walls.DiffuseColor = [0.75, 0.75, 0.8]
    walls.Opacity = 0.25
if CONTACTS:
    contacts = Show(series('contacts'), view)
    ColorBy(contacts, ('CELLS', 'normal_force'))
    contacts.LineWidth = 2.0
if BONDS:
    bonds = Show(series('bonds'), view)
    ColorBy(bonds, ('CELLS', 'utilisation'))
    bonds.LookupTable = GetColorTransferFunction('utilisation')
    bonds.LookupTable.ApplyPreset('Inferno (matplotlib)', True)
    bonds.LookupTable.RescaleTransferFunction(0.0, 1.0)
    bonds.LineWidth = 3.0

scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
scene.GoToLast()
shown.RescaleTransferFunctionToDataRange(False, True)
if CONTACTS:
    contacts.RescaleTransferFunctionToDataRange(False, True)
bar = GetScalarBar(shown.LookupTable, view)
bar.Title = 'coordination'
bar.ComponentTitle = ''

# Camera: from the front-left, a little above, the whole scene in view.
(x0, x1, y0, y1, z0, z1) = particles.GetDataInformation().GetBounds()
centre = [(x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2]
size = max(x1 - x0, y1 - y0, z1 - z0)
view.CameraFocalPoint = centre
view.CameraPosition = [centre[0] + 1.2 * size, centre[1] - 2.0 * size, centre[2] + 1.0 * size]
view.CameraViewUp = [0, 0, 1]
ResetCamera(view)
Render(view)

if '--png' in sys.argv:
    SaveScreenshot(sys.argv[sys.argv.index('--png') + 1], view, ImageResolution=[1280, 960], FontScaling='Do not scale fonts')
)";
  const auto replace = [&text](const std::string& key, const std::string& value) {
    text.replace(text.find(key), key.size(), value);  // each key once, in the text above
  };
  replace("@SURFACES", flag(series.surfaces));
  replace("@CONTACTS", flag(series.contacts));
  replace("@WALLS", flag(series.walls));
  replace("@BONDS", flag(series.bonds));
  writeFileAtomically(directory / (name + "_view.py"), text);
}

}  // namespace sqdem
