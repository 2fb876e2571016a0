// Lab 11 app: a scene editor's core, driven by scripts of editor commands in
// the cases (select, drag, material, undo, redo, save, tick). A click picks
// through the stencil buffer (your objectAtPixel(), stencil_pick.cpp), a drag
// on the gizmo moves along an axis (your dragAlongAxis(), gizmo.cpp), every
// edit goes through your EditHistory (history.cpp), and the panel's texture
// reloads when your assetsToReload() says so (hot_reload.cpp).
// editor_app.hpp lists the case keys and the window's keys.

#include "editor_app.hpp"

#include <stoa/lab/LabApp.hpp>

int main(int argc, char** argv) {
    stoa::EditorLabApp lab;
    return stoa::runLab(lab, STOA_LAB_BUILD_INFO, argc, argv);
}
