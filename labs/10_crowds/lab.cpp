// Lab 10 app: crowds of characters defined in XML, walking over a ground they
// know only through two images. Every step, each agent's behaviour (your
// stepStateMachine() or arbitrateLayers(), behaviour.cpp) picks its actions,
// the collision map (your walkableAt(), ground.cpp) keeps it off blocked
// ground and the height map (your heightAt()) sets its feet; the characters
// are Quake 2 MD2 models posed between two key frames (your md2FramesAt() and
// blendMd2Frames(), md2_blend.cpp). crowd_app.hpp lists the case keys.

#include "crowd_app.hpp"

#include <stoa/lab/LabApp.hpp>

int main(int argc, char** argv) {
    stoa::CrowdApp lab;
    return stoa::runLab(lab, STOA_LAB_BUILD_INFO, argc, argv);
}
