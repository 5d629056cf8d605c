# fxport_embed_effect(TARGET FX_FILE HEADER_NAME SYMBOL): makes <build>/generated/fxport_generated/
# HEADER_NAME declaring `inline constexpr const char* SYMBOL = R"fxport_fx(<FX_FILE's text>)fxport_fx";`
# in namespace fxport::detail, and adds it to TARGET. The built-in effects (SpriteBatch's,
# the stock effects) go through xlate at run time like any user effect; embedding them keeps
# the library free of install paths. Editing the .fx re-runs the configure step; file(CONFIGURE)
# rewrites the header only when the text changed.
function(fxport_embed_effect target fx_file header_name symbol)
  set(generated_dir ${CMAKE_CURRENT_BINARY_DIR}/generated)
  set(header ${generated_dir}/fxport_generated/${header_name})
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${fx_file})
  file(READ ${fx_file} FXPORT_EMBEDDED_TEXT)
  string(FIND "${FXPORT_EMBEDDED_TEXT}" ")fxport_fx\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${fx_file} contains the raw-string delimiter )fxport_fx\"")
  endif()
  get_filename_component(fx_name ${fx_file} NAME)
  set(FXPORT_EMBEDDED_SYMBOL ${symbol})
  set(FXPORT_EMBEDDED_NAME ${fx_name})
  # @ONLY: the .fx text is substituted once and never scanned for ${...}.
  file(CONFIGURE OUTPUT ${header} @ONLY CONTENT
"// GENERATED from runtime/graphics/shaders/@FXPORT_EMBEDDED_NAME@ by fxport_embed_effect. Do not edit.
#pragma once

namespace fxport::detail {
inline constexpr const char* @FXPORT_EMBEDDED_SYMBOL@ = R\"fxport_fx(@FXPORT_EMBEDDED_TEXT@)fxport_fx\";
}  // namespace fxport::detail
")
  target_sources(${target} PRIVATE ${header})
  target_include_directories(${target} PRIVATE ${generated_dir})
endfunction()
