# stoa-editor end to end (issue 16), included by tests/e2e/CMakeLists.txt where the
# window tests are defined (Xvfb and xdotool found; `work` is the tests' work folder):
#   editor_edit_save_reload           click, drag the gizmo, undo, redo, Ctrl+S; the saved
#                                     file differs only there and reopens to the same picture
#   editor_texture_reload             a texture renamed over reloads within a second and shows
#   editor_shader_error_keeps_drawing a typo in the shader panel names its line, the last good
#                                     program keeps drawing, the fix compiles
#   editor_renderer_settings          deferred shading, ambient occlusion, the normals view (no window)
#   editor_bad_scene_named            broken scene files and command lines (no window)
#   editor_showcase.BACKEND           the showcase headless: sky, lights, shadows; on the
#                                     last backend every debug view too (no window)
#   editor_keys_turn_scale            `.` and `=` turn and scale the selection, one edit each; undone
#   editor_crowd_reload               the crowd's world file saved anew starts the crowd again; a
#                                     broken save keeps it, the error at its line
#   window_showcase                   stoa-editor --scene showcase in a window: a frame, and
#                                     the crowd and lights moving
# The window tests take the Xvfb lock as the e2e.window_* tests do.
if(TARGET stoa-editor)
  set(editor_window_tests "")
  if(Python3_Interpreter_FOUND)
    add_test(NAME e2e.editor_edit_save_reload
             COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/editor_edit_save_reload.sh $<TARGET_FILE:stoa-editor>
                     $<TARGET_FILE:compare_images> ${work}/editor-edit-save-reload)
    add_test(NAME e2e.editor_texture_reload
             COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/editor_texture_reload.sh $<TARGET_FILE:stoa-editor>
                     ${work}/editor-texture-reload)
    add_test(NAME e2e.editor_shader_error_keeps_drawing
             COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/editor_shader_error_keeps_drawing.sh $<TARGET_FILE:stoa-editor>
                     ${work}/editor-shader-error)
    add_test(NAME e2e.window_showcase
             COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/window_showcase.sh $<TARGET_FILE:stoa-editor> ${work}/window-showcase)
    add_test(NAME e2e.editor_keys_turn_scale
             COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/editor_keys_turn_scale.sh $<TARGET_FILE:stoa-editor> ${work}/editor-keys-turn-scale)
    add_test(NAME e2e.editor_crowd_reload
             COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/editor_crowd_reload.sh $<TARGET_FILE:stoa-editor> ${work}/editor-crowd-reload)
    list(APPEND editor_window_tests e2e.editor_edit_save_reload e2e.editor_texture_reload
                e2e.editor_shader_error_keeps_drawing e2e.window_showcase e2e.editor_crowd_reload
                e2e.editor_keys_turn_scale)
    set_tests_properties(${editor_window_tests} PROPERTIES RESOURCE_LOCK xvfb)
    # Headless: the scene file's renderer settings drawn (forward, deferred, occlusion, normals).
    add_test(NAME e2e.editor_renderer_settings
             COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/editor_renderer_settings.sh $<TARGET_FILE:stoa-editor>
                     ${CMAKE_SOURCE_DIR} ${work}/editor-renderer-settings)
    # The showcase on each headless backend; the debug views on the last one.
    list(GET backends -1 last_backend)
    foreach(backend IN LISTS backends)
      set(views "")
      if(backend STREQUAL last_backend)
        set(views views)
      endif()
      add_test(NAME e2e.editor_showcase.${backend}
               COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/editor_showcase.sh $<TARGET_FILE:stoa-editor> ${CMAKE_SOURCE_DIR}
                       ${work}/editor-showcase-${backend} ${backend} ${views})
    endforeach()
  else()
    message(WARNING "python3 not found: the stoa-editor window tests (e2e.editor_*) are skipped")
  endif()
  add_test(NAME e2e.editor_bad_scene_named
           COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/editor_bad_scene_named.sh $<TARGET_FILE:stoa-editor>
                   ${work}/editor-bad-scene)
endif()
