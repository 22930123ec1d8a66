#!/usr/bin/env python3
"""gen_table.py - the fuzzer's table of entry points, generated at build time
from what libfixgl exports.

    gen_table.py --nm NM --lib libfixgl.so --header gl.h [--header ...] --out fz_table.c

Every `gl*` and `OSMesa*` symbol the shared library exports (nm -D) is looked
up among the prototypes of the headers given (Mesa's <GL/gl.h>, <GL/glext.h>,
fixgl's <GL/osmesa.h>) and classified: each parameter gets a kind (enum,
bitfield, boolean, integers of each width, GLsizei, float, double, input
pointer, output pointer) and, for enums, a class of values (the enums that
parameter accepts somewhere in GL 1.x).  A new entry point is fuzzed the day
it is exported; one whose prototype is not found, or whose parameter types
are unknown, fails the build (classify it here).  OSMesa functions that
create, destroy or look up contexts and procedures are not fuzzed (EXCLUDED,
with the reason); fixgl* (fixgl's own API, absent from the oracle) neither.

The output defines fz_table[] (names, kinds, classes), fz_enum_class[] and
fz_call_entry(), which calls entry i through the pointer fz_fn[i] that the
executor resolved at startup (the same source runs against either library).
"""
import argparse
import re
import subprocess
import sys

# --- parameter kinds --------------------------------------------------------
SCALAR = {
    'GLenum': ('FZ_ENUM', 'GLenum', 'u'),
    'GLbitfield': ('FZ_BITFIELD', 'GLbitfield', 'u'),
    'GLboolean': ('FZ_BOOL', 'GLboolean', 'u'),
    'GLbyte': ('FZ_I8', 'GLbyte', 'i'),
    'GLubyte': ('FZ_U8', 'GLubyte', 'u'),
    'GLshort': ('FZ_I16', 'GLshort', 'i'),
    'GLushort': ('FZ_U16', 'GLushort', 'u'),
    'GLint': ('FZ_I32', 'GLint', 'i'),
    'GLuint': ('FZ_U32', 'GLuint', 'u'),
    'GLsizei': ('FZ_SIZE', 'GLsizei', 'i'),
    'GLfloat': ('FZ_F32', 'GLfloat', 'f'),
    'GLclampf': ('FZ_F32', 'GLclampf', 'f'),
    'GLdouble': ('FZ_F64', 'GLdouble', 'f'),
    # buffer offsets and sizes (GL 1.5): 32-bit values, sign-extended
    'GLsizeiptr': ('FZ_SIZE', 'GLsizeiptr', 'i'),
    'GLintptr': ('FZ_SIZE', 'GLintptr', 'i'),
    'GLsizeiptrARB': ('FZ_SIZE', 'GLsizeiptrARB', 'i'),
    'GLintptrARB': ('FZ_SIZE', 'GLintptrARB', 'i'),
    'GLclampd': ('FZ_F64', 'GLclampd', 'f'),
    'OSMesaContext': ('FZ_CTX', 'OSMesaContext', 'p'),
}
RETURNS = {'void': 'FZ_RET_VOID', 'GLboolean': 'FZ_RET_INT', 'GLint': 'FZ_RET_INT',
           'GLuint': 'FZ_RET_INT', 'GLenum': 'FZ_RET_INT',
           'const GLubyte *': 'FZ_RET_PTR'}

# OSMesa functions not fuzzed, with the reason.
EXCLUDED = {
    'OSMesaCreateContext': 'creates contexts: the stream runs in the one context the executor made',
    'OSMesaCreateContextExt': 'creates contexts: the stream runs in the one context the executor made',
    'OSMesaCreateContextAttribs': 'creates contexts: the stream runs in the one context the executor made',
    'OSMesaDestroyContext': 'would destroy the context every later call runs in',
    'OSMesaGetCurrentContext': 'returns a handle, no state',
    'OSMesaGetProcAddress': 'takes a string; covered by the query walk case',
    'OSMesaPostprocess': 'Mesa\'s post-processing filters: a string argument, not in fixgl\'s scope',
}

# --- enum classes -----------------------------------------------------------
# name -> list of enum names (or regular expressions on names, prefixed '~').
CLASSES = {
    'primitive': ['GL_POINTS', 'GL_LINES', 'GL_LINE_LOOP', 'GL_LINE_STRIP', 'GL_TRIANGLES',
                  'GL_TRIANGLE_STRIP', 'GL_TRIANGLE_FAN', 'GL_QUADS', 'GL_QUAD_STRIP', 'GL_POLYGON'],
    'cap': ['GL_ALPHA_TEST', 'GL_AUTO_NORMAL', 'GL_BLEND', 'GL_CLIP_PLANE0', 'GL_CLIP_PLANE5',
            'GL_COLOR_LOGIC_OP', 'GL_COLOR_MATERIAL', 'GL_CULL_FACE', 'GL_DEPTH_TEST', 'GL_DITHER',
            'GL_FOG', 'GL_INDEX_LOGIC_OP', 'GL_LIGHT0', 'GL_LIGHT1', 'GL_LIGHT7', 'GL_LIGHTING',
            'GL_LINE_SMOOTH', 'GL_LINE_STIPPLE', 'GL_MAP1_COLOR_4', 'GL_MAP1_INDEX', 'GL_MAP1_NORMAL',
            'GL_MAP1_TEXTURE_COORD_1', 'GL_MAP1_TEXTURE_COORD_2', 'GL_MAP1_TEXTURE_COORD_3',
            'GL_MAP1_TEXTURE_COORD_4', 'GL_MAP1_VERTEX_3', 'GL_MAP1_VERTEX_4', 'GL_MAP2_COLOR_4',
            'GL_MAP2_INDEX', 'GL_MAP2_NORMAL', 'GL_MAP2_TEXTURE_COORD_1', 'GL_MAP2_TEXTURE_COORD_2',
            'GL_MAP2_TEXTURE_COORD_3', 'GL_MAP2_TEXTURE_COORD_4', 'GL_MAP2_VERTEX_3',
            'GL_MAP2_VERTEX_4', 'GL_NORMALIZE', 'GL_POINT_SMOOTH', 'GL_POLYGON_OFFSET_FILL',
            'GL_POLYGON_OFFSET_LINE', 'GL_POLYGON_OFFSET_POINT', 'GL_POLYGON_SMOOTH',
            'GL_POLYGON_STIPPLE', 'GL_SCISSOR_TEST', 'GL_STENCIL_TEST', 'GL_TEXTURE_1D',
            'GL_TEXTURE_2D', 'GL_TEXTURE_GEN_Q', 'GL_TEXTURE_GEN_R', 'GL_TEXTURE_GEN_S',
            'GL_TEXTURE_GEN_T', 'GL_RESCALE_NORMAL', 'GL_MULTISAMPLE', 'GL_SAMPLE_COVERAGE',
            'GL_SAMPLE_ALPHA_TO_COVERAGE', 'GL_SAMPLE_ALPHA_TO_ONE', 'GL_TEXTURE_3D',
            'GL_TEXTURE_CUBE_MAP'],
    'client_array': ['GL_VERTEX_ARRAY', 'GL_NORMAL_ARRAY', 'GL_COLOR_ARRAY', 'GL_INDEX_ARRAY',
                     'GL_TEXTURE_COORD_ARRAY', 'GL_EDGE_FLAG_ARRAY'],
    'type_vertex': ['GL_SHORT', 'GL_INT', 'GL_FLOAT', 'GL_DOUBLE', 'GL_BYTE', 'GL_UNSIGNED_BYTE',
                    'GL_UNSIGNED_SHORT', 'GL_UNSIGNED_INT'],
    'type_index': ['GL_UNSIGNED_BYTE', 'GL_UNSIGNED_SHORT', 'GL_UNSIGNED_INT', 'GL_INT'],
    'type_lists': ['GL_BYTE', 'GL_UNSIGNED_BYTE', 'GL_SHORT', 'GL_UNSIGNED_SHORT', 'GL_INT',
                   'GL_UNSIGNED_INT', 'GL_FLOAT', 'GL_2_BYTES', 'GL_3_BYTES', 'GL_4_BYTES'],
    'type_pixel': ['GL_UNSIGNED_BYTE', 'GL_BYTE', 'GL_BITMAP', 'GL_UNSIGNED_SHORT', 'GL_SHORT',
                   'GL_UNSIGNED_INT', 'GL_INT', 'GL_FLOAT', 'GL_UNSIGNED_BYTE_3_3_2',
                   'GL_UNSIGNED_BYTE_2_3_3_REV', 'GL_UNSIGNED_SHORT_5_6_5',
                   'GL_UNSIGNED_SHORT_5_6_5_REV', 'GL_UNSIGNED_SHORT_4_4_4_4',
                   'GL_UNSIGNED_SHORT_4_4_4_4_REV', 'GL_UNSIGNED_SHORT_5_5_5_1',
                   'GL_UNSIGNED_SHORT_1_5_5_5_REV', 'GL_UNSIGNED_INT_8_8_8_8',
                   'GL_UNSIGNED_INT_8_8_8_8_REV', 'GL_UNSIGNED_INT_10_10_10_2',
                   'GL_UNSIGNED_INT_2_10_10_10_REV'],
    'format_pixel': ['GL_COLOR_INDEX', 'GL_STENCIL_INDEX', 'GL_DEPTH_COMPONENT', 'GL_RED',
                     'GL_GREEN', 'GL_BLUE', 'GL_ALPHA', 'GL_RGB', 'GL_RGBA', 'GL_BGR', 'GL_BGRA',
                     'GL_LUMINANCE', 'GL_LUMINANCE_ALPHA'],
    'internalformat': ['GL_ALPHA', 'GL_ALPHA4', 'GL_ALPHA8', 'GL_ALPHA12', 'GL_ALPHA16',
                       'GL_LUMINANCE', 'GL_LUMINANCE4', 'GL_LUMINANCE8', 'GL_LUMINANCE16',
                       'GL_LUMINANCE_ALPHA', 'GL_LUMINANCE4_ALPHA4', 'GL_LUMINANCE8_ALPHA8',
                       'GL_INTENSITY', 'GL_INTENSITY4', 'GL_INTENSITY8', 'GL_INTENSITY16',
                       'GL_R3_G3_B2', 'GL_RGB', 'GL_RGB4', 'GL_RGB5', 'GL_RGB8', 'GL_RGB10',
                       'GL_RGB12', 'GL_RGB16', 'GL_RGBA', 'GL_RGBA2', 'GL_RGBA4', 'GL_RGB5_A1',
                       'GL_RGBA8', 'GL_RGB10_A2', 'GL_RGBA12', 'GL_RGBA16', 'GL_DEPTH_COMPONENT',
                       'GL_DEPTH_COMPONENT16', 'GL_DEPTH_COMPONENT24', 'GL_DEPTH_COMPONENT32',
                       'GL_COLOR_INDEX', 'GL_BGRA', 'GL_RED'],
    # (three of the six cube-map faces; the others come from the hostile
    # choices: any GL enum)
    'tex_target': ['GL_TEXTURE_1D', 'GL_TEXTURE_2D', 'GL_PROXY_TEXTURE_1D', 'GL_PROXY_TEXTURE_2D',
                   'GL_TEXTURE_3D', 'GL_TEXTURE_CUBE_MAP', 'GL_PROXY_TEXTURE_3D',
                   'GL_PROXY_TEXTURE_CUBE_MAP', 'GL_TEXTURE_CUBE_MAP_POSITIVE_X',
                   'GL_TEXTURE_CUBE_MAP_NEGATIVE_Y', 'GL_TEXTURE_CUBE_MAP_POSITIVE_Z'],
    # glCompressedTex*: the S3TC formats fixgl has, a generic one, one fixgl
    # lacks (FXT1) and an uncompressed one
    'compressed_format': ['GL_COMPRESSED_RGB_S3TC_DXT1_EXT', 'GL_COMPRESSED_RGBA_S3TC_DXT1_EXT',
                          'GL_COMPRESSED_RGBA_S3TC_DXT3_EXT', 'GL_COMPRESSED_RGBA_S3TC_DXT5_EXT',
                          'GL_COMPRESSED_RGB', 'GL_RGBA'],
    'tex_pname': ['GL_TEXTURE_MIN_FILTER', 'GL_TEXTURE_MAG_FILTER', 'GL_TEXTURE_WRAP_S',
                  'GL_TEXTURE_WRAP_T', 'GL_TEXTURE_WRAP_R', 'GL_TEXTURE_BORDER_COLOR',
                  'GL_TEXTURE_PRIORITY', 'GL_TEXTURE_MIN_LOD', 'GL_TEXTURE_MAX_LOD',
                  'GL_TEXTURE_BASE_LEVEL', 'GL_TEXTURE_MAX_LEVEL', 'GL_GENERATE_MIPMAP',
                  'GL_TEXTURE_LOD_BIAS', 'GL_TEXTURE_RESIDENT', 'GL_DEPTH_TEXTURE_MODE',
                  'GL_TEXTURE_COMPARE_MODE', 'GL_TEXTURE_COMPARE_FUNC'],
    'tex_level_pname': ['GL_TEXTURE_WIDTH', 'GL_TEXTURE_HEIGHT', 'GL_TEXTURE_DEPTH',
                        'GL_TEXTURE_INTERNAL_FORMAT', 'GL_TEXTURE_BORDER', 'GL_TEXTURE_RED_SIZE',
                        'GL_TEXTURE_GREEN_SIZE', 'GL_TEXTURE_BLUE_SIZE', 'GL_TEXTURE_ALPHA_SIZE',
                        'GL_TEXTURE_LUMINANCE_SIZE', 'GL_TEXTURE_INTENSITY_SIZE',
                        'GL_TEXTURE_DEPTH_SIZE'],
    'texenv_target': ['GL_TEXTURE_ENV', 'GL_TEXTURE_FILTER_CONTROL', 'GL_POINT_SPRITE'],
    'texenv_pname': ['GL_TEXTURE_ENV_MODE', 'GL_TEXTURE_ENV_COLOR', 'GL_COMBINE_RGB',
                     'GL_COMBINE_ALPHA', 'GL_SOURCE0_RGB', 'GL_SOURCE1_RGB', 'GL_SOURCE2_RGB',
                     'GL_SOURCE0_ALPHA', 'GL_OPERAND0_RGB', 'GL_OPERAND1_RGB', 'GL_OPERAND0_ALPHA',
                     'GL_RGB_SCALE', 'GL_ALPHA_SCALE', 'GL_TEXTURE_LOD_BIAS'],
    'texgen_coord': ['GL_S', 'GL_T', 'GL_R', 'GL_Q'],
    'texgen_pname': ['GL_TEXTURE_GEN_MODE', 'GL_OBJECT_PLANE', 'GL_EYE_PLANE'],
    'light': ['GL_LIGHT0', 'GL_LIGHT1', 'GL_LIGHT2', 'GL_LIGHT7'],
    'light_pname': ['GL_AMBIENT', 'GL_DIFFUSE', 'GL_SPECULAR', 'GL_POSITION', 'GL_SPOT_DIRECTION',
                    'GL_SPOT_EXPONENT', 'GL_SPOT_CUTOFF', 'GL_CONSTANT_ATTENUATION',
                    'GL_LINEAR_ATTENUATION', 'GL_QUADRATIC_ATTENUATION'],
    'lightmodel_pname': ['GL_LIGHT_MODEL_AMBIENT', 'GL_LIGHT_MODEL_LOCAL_VIEWER',
                         'GL_LIGHT_MODEL_TWO_SIDE', 'GL_LIGHT_MODEL_COLOR_CONTROL'],
    'face': ['GL_FRONT', 'GL_BACK', 'GL_FRONT_AND_BACK'],
    'material_pname': ['GL_AMBIENT', 'GL_DIFFUSE', 'GL_SPECULAR', 'GL_EMISSION', 'GL_SHININESS',
                       'GL_AMBIENT_AND_DIFFUSE', 'GL_COLOR_INDEXES'],
    'fog_pname': ['GL_FOG_MODE', 'GL_FOG_DENSITY', 'GL_FOG_START', 'GL_FOG_END', 'GL_FOG_INDEX',
                  'GL_FOG_COLOR', 'GL_FOG_COORDINATE_SOURCE'],
    'pixelstore_pname': ['GL_UNPACK_SWAP_BYTES', 'GL_UNPACK_LSB_FIRST', 'GL_UNPACK_ROW_LENGTH',
                         'GL_UNPACK_SKIP_ROWS', 'GL_UNPACK_SKIP_PIXELS', 'GL_UNPACK_ALIGNMENT',
                         'GL_PACK_SWAP_BYTES', 'GL_PACK_LSB_FIRST', 'GL_PACK_ROW_LENGTH',
                         'GL_PACK_SKIP_ROWS', 'GL_PACK_SKIP_PIXELS', 'GL_PACK_ALIGNMENT'],
    'pixeltransfer_pname': ['GL_MAP_COLOR', 'GL_MAP_STENCIL', 'GL_INDEX_SHIFT', 'GL_INDEX_OFFSET',
                            'GL_RED_SCALE', 'GL_RED_BIAS', 'GL_GREEN_SCALE', 'GL_GREEN_BIAS',
                            'GL_BLUE_SCALE', 'GL_BLUE_BIAS', 'GL_ALPHA_SCALE', 'GL_ALPHA_BIAS',
                            'GL_DEPTH_SCALE', 'GL_DEPTH_BIAS'],
    'pixelmap': ['~^GL_PIXEL_MAP_[A-Z]_TO_[A-Z]$'],
    'eval_target': ['~^GL_MAP[12]_(COLOR_4|INDEX|NORMAL|TEXTURE_COORD_[1-4]|VERTEX_[34])$'],
    'getmap_query': ['GL_COEFF', 'GL_ORDER', 'GL_DOMAIN'],
    'mesh_mode': ['GL_POINT', 'GL_LINE', 'GL_FILL'],
    'func': ['GL_NEVER', 'GL_LESS', 'GL_EQUAL', 'GL_LEQUAL', 'GL_GREATER', 'GL_NOTEQUAL',
             'GL_GEQUAL', 'GL_ALWAYS'],
    'stencil_op': ['GL_KEEP', 'GL_ZERO', 'GL_REPLACE', 'GL_INCR', 'GL_DECR', 'GL_INVERT',
                   'GL_INCR_WRAP', 'GL_DECR_WRAP'],
    'blend_factor': ['GL_ZERO', 'GL_ONE', 'GL_SRC_COLOR', 'GL_ONE_MINUS_SRC_COLOR', 'GL_DST_COLOR',
                     'GL_ONE_MINUS_DST_COLOR', 'GL_SRC_ALPHA', 'GL_ONE_MINUS_SRC_ALPHA',
                     'GL_DST_ALPHA', 'GL_ONE_MINUS_DST_ALPHA', 'GL_SRC_ALPHA_SATURATE',
                     'GL_CONSTANT_COLOR', 'GL_ONE_MINUS_CONSTANT_COLOR', 'GL_CONSTANT_ALPHA',
                     'GL_ONE_MINUS_CONSTANT_ALPHA'],
    'blend_equation': ['GL_FUNC_ADD', 'GL_FUNC_SUBTRACT', 'GL_FUNC_REVERSE_SUBTRACT', 'GL_MIN',
                       'GL_MAX', 'GL_LOGIC_OP'],
    'logic_op': ['~^GL_(CLEAR|AND|AND_REVERSE|COPY|AND_INVERTED|NOOP|XOR|OR|NOR|EQUIV|INVERT|'
                 'OR_REVERSE|COPY_INVERTED|OR_INVERTED|NAND|SET)$'],
    'matrix_mode': ['GL_MODELVIEW', 'GL_PROJECTION', 'GL_TEXTURE', 'GL_COLOR'],
    'polygon_mode': ['GL_POINT', 'GL_LINE', 'GL_FILL'],
    'front_face': ['GL_CW', 'GL_CCW'],
    'shade_model': ['GL_FLAT', 'GL_SMOOTH'],
    'hint_target': ['GL_PERSPECTIVE_CORRECTION_HINT', 'GL_POINT_SMOOTH_HINT', 'GL_LINE_SMOOTH_HINT',
                    'GL_POLYGON_SMOOTH_HINT', 'GL_FOG_HINT', 'GL_GENERATE_MIPMAP_HINT',
                    'GL_TEXTURE_COMPRESSION_HINT'],
    'hint_mode': ['GL_FASTEST', 'GL_NICEST', 'GL_DONT_CARE'],
    'buffer': ['GL_NONE', 'GL_FRONT_LEFT', 'GL_FRONT_RIGHT', 'GL_BACK_LEFT', 'GL_BACK_RIGHT',
               'GL_FRONT', 'GL_BACK', 'GL_LEFT', 'GL_RIGHT', 'GL_FRONT_AND_BACK', 'GL_AUX0'],
    'copy_type': ['GL_COLOR', 'GL_DEPTH', 'GL_STENCIL'],
    'accum_op': ['GL_ACCUM', 'GL_LOAD', 'GL_RETURN', 'GL_MULT', 'GL_ADD'],
    'list_mode': ['GL_COMPILE', 'GL_COMPILE_AND_EXECUTE'],
    'render_mode': ['GL_RENDER', 'GL_SELECT', 'GL_FEEDBACK'],
    'feedback_type': ['GL_2D', 'GL_3D', 'GL_3D_COLOR', 'GL_3D_COLOR_TEXTURE', 'GL_4D_COLOR_TEXTURE'],
    'interleaved': ['GL_V2F', 'GL_V3F', 'GL_C4UB_V2F', 'GL_C4UB_V3F', 'GL_C3F_V3F', 'GL_N3F_V3F',
                    'GL_C4F_N3F_V3F', 'GL_T2F_V3F', 'GL_T4F_V4F', 'GL_T2F_C4UB_V3F',
                    'GL_T2F_C3F_V3F', 'GL_T2F_N3F_V3F', 'GL_T2F_C4F_N3F_V3F',
                    'GL_T4F_C4F_N3F_V4F'],
    'texture_unit': ['GL_TEXTURE0', 'GL_TEXTURE1', 'GL_TEXTURE2', 'GL_TEXTURE3', 'GL_TEXTURE7',
                     'GL_TEXTURE8', 'GL_TEXTURE31'],
    'clip_plane': ['GL_CLIP_PLANE0', 'GL_CLIP_PLANE1', 'GL_CLIP_PLANE5'],
    'color_material': ['GL_EMISSION', 'GL_AMBIENT', 'GL_DIFFUSE', 'GL_SPECULAR',
                       'GL_AMBIENT_AND_DIFFUSE'],
    'string_name': ['GL_VENDOR', 'GL_RENDERER', 'GL_VERSION', 'GL_EXTENSIONS'],
    'pointer_pname': ['GL_VERTEX_ARRAY_POINTER', 'GL_NORMAL_ARRAY_POINTER',
                      'GL_COLOR_ARRAY_POINTER', 'GL_INDEX_ARRAY_POINTER',
                      'GL_TEXTURE_COORD_ARRAY_POINTER', 'GL_EDGE_FLAG_ARRAY_POINTER',
                      'GL_FEEDBACK_BUFFER_POINTER', 'GL_SELECTION_BUFFER_POINTER'],
    'get_pname': ['~^GL_(CURRENT|VERTEX_ARRAY|COLOR_ARRAY|TEXTURE_BINDING|MODELVIEW|PROJECTION|'
                  'VIEWPORT|DEPTH|STENCIL|BLEND|FOG|LIGHT|POINT|LINE|POLYGON|PIXEL_MAP|MAX|'
                  'UNPACK|PACK|LIST|ATTRIB|NAME_STACK|RENDER_MODE|SELECTION|FEEDBACK|ALPHA|'
                  'SCISSOR|COLOR|INDEX|ACCUM|MAP[12]|TEXTURE|ZOOM|RED|GREEN|BLUE|'
                  'CLIENT|ACTIVE|EDGE|CULL|FRONT|SHADE|MATRIX|NORMAL|AUX|DRAW|READ|AUTO|'
                  'SUBPIXEL|RGBA|DOUBLE|STEREO|SAMPLE|DITHER|LOGIC)'],
    'attrib_mask': [],
    # GL 1.5 buffer objects and occlusion queries
    'buffer_target': ['GL_ARRAY_BUFFER', 'GL_ELEMENT_ARRAY_BUFFER'],
    'buffer_usage': ['GL_STREAM_DRAW', 'GL_STREAM_READ', 'GL_STREAM_COPY', 'GL_STATIC_DRAW',
                     'GL_STATIC_READ', 'GL_STATIC_COPY', 'GL_DYNAMIC_DRAW', 'GL_DYNAMIC_READ',
                     'GL_DYNAMIC_COPY'],
    'buffer_access': ['GL_READ_ONLY', 'GL_WRITE_ONLY', 'GL_READ_WRITE'],
    'buffer_pname': ['GL_BUFFER_SIZE', 'GL_BUFFER_USAGE', 'GL_BUFFER_ACCESS', 'GL_BUFFER_MAPPED'],
    'buffer_pointer_pname': ['GL_BUFFER_MAP_POINTER'],
    'query_target': ['GL_SAMPLES_PASSED'],
    'query_pname': ['GL_QUERY_COUNTER_BITS', 'GL_CURRENT_QUERY'],
    'query_object_pname': ['GL_QUERY_RESULT', 'GL_QUERY_RESULT_AVAILABLE'],
}
# GLbitfield classes (combinations of these bits and random masks).
BITS = {
    'glClear': ['GL_COLOR_BUFFER_BIT', 'GL_DEPTH_BUFFER_BIT', 'GL_STENCIL_BUFFER_BIT',
                'GL_ACCUM_BUFFER_BIT'],
    'glPushAttrib': ['~^GL_[A-Z_]+_BIT$'],
    'glPushClientAttrib': ['GL_CLIENT_PIXEL_STORE_BIT', 'GL_CLIENT_VERTEX_ARRAY_BIT'],
}

# (function regex, parameter name) -> class; first match wins; then by name.
RULES = [
    (r'^glBegin$', 'mode', 'primitive'),
    (r'^gl(Draw(Arrays|Elements|RangeElements))(EXT)?$', 'mode', 'primitive'),
    (r'^glEvalMesh', 'mode', 'mesh_mode'),
    (r'^gl(Enable|Disable|IsEnabled)$', 'cap', 'cap'),
    (r'^gl(Enable|Disable)ClientState$', 'array', 'client_array'),
    (r'^gl(Vertex|Normal|Color|TexCoord|Index)Pointer(EXT)?$', 'type', 'type_vertex'),
    (r'^glDraw(Range)?Elements$', 'type', 'type_index'),
    (r'^glCallLists$', 'type', 'type_lists'),
    (r'^gl(TexImage|TexSubImage|DrawPixels|ReadPixels|GetTexImage)', 'type', 'type_pixel'),
    (r'^gl(TexImage|TexSubImage|DrawPixels|ReadPixels|GetTexImage)', 'format', 'format_pixel'),
    (r'^gl(Tex|CopyTex|GetTex|BindTexture|CompressedTex|GetCompressedTex)', 'target', 'tex_target'),
    (r'^glCompressedTex', 'internalformat', 'compressed_format'),
    (r'^glCompressedTex', 'format', 'compressed_format'),
    (r'^gl(Tex|CopyTex)', 'internalFormat', 'internalformat'),
    (r'^gl(Tex|CopyTex)', 'internalformat', 'internalformat'),
    (r'^gl(Get)?TexParameter', 'pname', 'tex_pname'),
    (r'^glGetTexLevelParameter', 'pname', 'tex_level_pname'),
    (r'^gl(Get)?TexEnv', 'target', 'texenv_target'),
    (r'^gl(Get)?TexEnv', 'pname', 'texenv_pname'),
    (r'^gl(Get)?TexGen', 'coord', 'texgen_coord'),
    (r'^gl(Get)?TexGen', 'pname', 'texgen_pname'),
    (r'^gl(Get)?Light[fi]', 'light', 'light'),
    (r'^gl(Get)?Light[fi]', 'pname', 'light_pname'),
    (r'^glLightModel', 'pname', 'lightmodel_pname'),
    (r'^gl(Get)?Material', 'pname', 'material_pname'),
    (r'^glColorMaterial$', 'mode', 'color_material'),
    (r'^glFog', 'pname', 'fog_pname'),
    (r'^glPixelStore', 'pname', 'pixelstore_pname'),
    (r'^glPixelTransfer', 'pname', 'pixeltransfer_pname'),
    (r'^gl(Get)?PixelMap', 'map', 'pixelmap'),
    (r'^glMap[12]', 'target', 'eval_target'),
    (r'^glGetMap', 'target', 'eval_target'),
    (r'^glGetMap', 'query', 'getmap_query'),
    (r'^gl(Depth|Alpha)Func$', 'func', 'func'),
    (r'^glStencilFunc$', 'func', 'func'),
    (r'^glStencilOp$', '*', 'stencil_op'),
    (r'^glBlendFunc$', '*', 'blend_factor'),
    (r'^glBlendEquation$', 'mode', 'blend_equation'),
    (r'^glLogicOp$', 'opcode', 'logic_op'),
    (r'^glMatrixMode$', 'mode', 'matrix_mode'),
    (r'^glPolygonMode$', 'face', 'face'),
    (r'^glPolygonMode$', 'mode', 'polygon_mode'),
    (r'^glCullFace$', 'mode', 'face'),
    (r'^glFrontFace$', 'mode', 'front_face'),
    (r'^glShadeModel$', 'mode', 'shade_model'),
    (r'^glHint$', 'target', 'hint_target'),
    (r'^glHint$', 'mode', 'hint_mode'),
    (r'^gl(Draw|Read)Buffer$', 'mode', 'buffer'),
    (r'^glCopyPixels$', 'type', 'copy_type'),
    (r'^glAccum$', 'op', 'accum_op'),
    (r'^glNewList$', 'mode', 'list_mode'),
    (r'^glRenderMode$', 'mode', 'render_mode'),
    (r'^glFeedbackBuffer$', 'type', 'feedback_type'),
    (r'^glInterleavedArrays$', 'format', 'interleaved'),
    (r'^gl(Client)?ActiveTexture', 'texture', 'texture_unit'),
    (r'^glMultiTexCoord', 'target', 'texture_unit'),
    (r'^gl(Get)?ClipPlane$', 'plane', 'clip_plane'),
    (r'^gl(Get)?Material|^glColorMaterial$', 'face', 'face'),
    (r'^glGetString$', 'name', 'string_name'),
    (r'^glGetPointerv(EXT)?$', 'pname', 'pointer_pname'),
    (r'^gl(BindBuffer|BufferData|BufferSubData|GetBufferSubData|MapBuffer|UnmapBuffer|'
     r'GetBufferParameteriv|GetBufferPointerv)(ARB)?$', 'target', 'buffer_target'),
    (r'^glBufferData(ARB)?$', 'usage', 'buffer_usage'),
    (r'^glMapBuffer(ARB)?$', 'access', 'buffer_access'),
    (r'^glGetBufferParameteriv(ARB)?$', 'pname', 'buffer_pname'),
    (r'^glGetBufferPointerv(ARB)?$', 'pname', 'buffer_pointer_pname'),
    (r'^gl(BeginQuery|EndQuery|GetQueryiv)(ARB)?$', 'target', 'query_target'),
    (r'^glGetQueryiv(ARB)?$', 'pname', 'query_pname'),
    (r'^glGetQueryObjectu?iv(ARB)?$', 'pname', 'query_object_pname'),
    (r'^glGet(Boolean|Integer|Float|Double)v$', 'pname', 'get_pname'),
]


def parse_enums(paths):
    enums = {}
    for path in paths:
        with open(path) as f:
            for m in re.finditer(r'^#define\s+(GL_[A-Z0-9_]+)\s+(0x[0-9A-Fa-f]+|\d+)\s*$',
                                 f.read(), re.M):
                enums.setdefault(m.group(1), int(m.group(2), 0))
    return enums


def parse_prototypes(paths):
    protos = {}
    for path in paths:
        with open(path) as f:
            text = f.read()
        text = re.sub(r'/\*.*?\*/', ' ', text, flags=re.S)
        for m in re.finditer(r'GLAPI\s+([\w\s\*]+?)\s*\b(?:GLAPIENTRY|APIENTRY)\s+(\w+)\s*\(([^)]*)\)',
                             text):
            ret, name, params = m.group(1), m.group(2), m.group(3)
            protos.setdefault(name, (' '.join(ret.split()), ' '.join(params.split())))
    return protos


def expand(names, enums):
    out = []
    for n in names:
        if n.startswith('~'):
            rx = re.compile(n[1:])
            out += sorted(k for k in enums if rx.search(k) and enums[k] < 0x10000)
        elif n in enums:
            out.append(n)
        else:
            sys.exit('gen_table.py: unknown enum %s' % n)
    seen, res = set(), []
    for n in out:
        if enums[n] not in seen:
            seen.add(enums[n])
            res.append(n)
    return res


def classify_param(fname, p):
    p = p.strip()
    # glMultiDrawElements' index lists: an array of input pointers (the
    # generator points it at the arena's pointer table, fz_gen.c)
    m = re.match(r'^const\s+(?:void|GLvoid)\s*\*\s*const\s*\*\s*(\w+)$', p)
    if m:
        return ('FZ_PTR_IN', 'const void *const *', m.group(1), 'p')
    m = re.match(r'^(const\s+)?(\w+)\s*(\*\s*\*|\*)?\s*(\w+)?\s*(\[\s*\d*\s*\])?$', p)
    if not m:
        return None
    const, typ, ptr, pname, arr = m.groups()
    pname = pname or ''
    if ptr or arr:
        if ptr and ptr.replace(' ', '') == '**':
            return ('FZ_PTR_OUT', 'GLvoid **', pname, 'p')
        ctype = ('const ' if const else '') + typ + ' *'
        return ('FZ_PTR_IN' if const else 'FZ_PTR_OUT', ctype, pname, 'p')
    if typ not in SCALAR:
        return None
    kind, ctype, conv = SCALAR[typ]
    return (kind, ctype, pname, conv)


def enum_class(fname, pname):
    for rx, pn, cls in RULES:
        if re.search(rx, fname) and (pn == '*' or pn == pname):
            return cls
    return None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--nm', required=True)
    ap.add_argument('--lib', required=True)
    ap.add_argument('--header', action='append', required=True)
    ap.add_argument('--out', required=True)
    a = ap.parse_args()

    syms = subprocess.run([a.nm, '-D', '--defined-only', a.lib], check=True,
                          capture_output=True, text=True).stdout.split('\n')
    exported = sorted({l.split()[-1] for l in syms if l.strip()
                       and re.match(r'^(gl|OSMesa)[A-Z]', l.split()[-1])})
    protos = parse_prototypes(a.header)
    enums = parse_enums([h for h in a.header if h.endswith('gl.h')])
    all_enums = parse_enums(a.header)

    class_ids = {}
    class_list = []
    entries = []
    excluded = []
    for name in exported:
        if name in EXCLUDED:
            excluded.append((name, EXCLUDED[name]))
            continue
        if name not in protos:
            sys.exit('gen_table.py: %s is exported but has no prototype in %s: '
                     'classify it in conformance/fuzz/gen_table.py' % (name, ', '.join(a.header)))
        ret, params = protos[name]
        if ret not in RETURNS and not ret.endswith('*'):
            sys.exit('gen_table.py: %s returns %s: unknown return type' % (name, ret))
        plist = [] if params.strip() in ('', 'void', 'GLvoid') else params.split(',')
        ps = []
        for p in plist:
            c = classify_param(name, p)
            if c is None:
                sys.exit('gen_table.py: %s: parameter "%s" of an unknown type' % (name, p))
            kind, ctype, pname, conv = c
            cls = None
            if kind == 'FZ_ENUM':
                cls = enum_class(name, pname)
            elif kind == 'FZ_BITFIELD':
                cls = ('bits:' + name) if name in BITS else None
            if cls is not None and cls not in class_ids:
                names = BITS[name] if cls.startswith('bits:') else CLASSES[cls]
                class_ids[cls] = len(class_list)
                class_list.append((cls, expand(names, all_enums)))
            ps.append((kind, ctype, pname, conv, class_ids.get(cls, -1)))
        if len(ps) > 12:
            sys.exit('gen_table.py: %s has more than 12 parameters' % name)
        entries.append((name, ret, ps))

    o = []
    o.append('/* Generated by conformance/fuzz/gen_table.py from the symbols libfixgl exports. */')
    o.append('#include "fz_table.h"\n')
    o.append('/* Not fuzzed:')
    for n, why in excluded:
        o.append(' *   %s: %s' % (n, why))
    o.append(' *   fixgl*: fixgl\'s own API, which the oracle does not have */\n')
    for i, (cls, names) in enumerate(class_list):
        o.append('static const uint32_t fz_class%d[] = { /* %s */' % (i, cls))
        o.append('    ' + ', '.join('0x%x' % all_enums[n] for n in names) + (',' if names else '0'))
        o.append('};')
    o.append('const fz_enum_class fz_enum_classes[] = {')
    for i, (cls, names) in enumerate(class_list):
        o.append('    { "%s", fz_class%d, %d },' % (cls, i, len(names)))
    o.append('};')
    o.append('const size_t fz_enum_class_count = %d;\n' % len(class_list))
    gl_enums = sorted({v for k, v in enums.items() if v < 0x10000})
    o.append('const uint32_t fz_all_enums[] = {')
    for i in range(0, len(gl_enums), 12):
        o.append('    ' + ', '.join('0x%x' % v for v in gl_enums[i:i + 12]) + ',')
    o.append('};')
    o.append('const size_t fz_all_enum_count = %d;\n' % len(gl_enums))
    o.append('const fz_entry fz_table[] = {')
    for name, ret, ps in entries:
        rk = RETURNS.get(ret, 'FZ_RET_PTR')
        kinds = ', '.join('{ %s, %d, "%s" }' % (k, cls, pn) for k, _, pn, _, cls in ps)
        o.append('    { "%s", %s, %d, { %s } },' % (name, rk, len(ps), kinds or '{ 0, 0, 0 }'))
    o.append('};')
    o.append('const size_t fz_table_count = %d;\n' % len(entries))
    o.append('#ifdef FZ_WITH_CALLS')
    o.append('fz_proc fz_fn[%d];\n' % len(entries))
    o.append('uint64_t fz_call_entry(size_t i, const fz_arg *a)\n{')
    o.append('    switch (i) {')
    for i, (name, ret, ps) in enumerate(entries):
        args = []
        for j, (k, ctype, pn, conv, cls) in enumerate(ps):
            if conv == 'p':
                args.append('(%s)fz_ptr(%s, a[%d].i)' % (ctype, k if k != 'FZ_CTX' else 'FZ_CTX', j))
            elif conv == 'f':
                args.append('(%s)a[%d].d' % (ctype, j))
            elif conv == 'i':
                args.append('(%s)(int32_t)a[%d].i' % (ctype, j))
            else:
                args.append('(%s)(uint32_t)a[%d].i' % (ctype, j))
        proto = ', '.join(c for _, c, _, _, _ in ps) or 'void'
        call = '((%s (GLAPIENTRY *)(%s))fz_fn[%d])(%s)' % (ret, proto, i, ', '.join(args))
        rk = RETURNS.get(ret, 'FZ_RET_PTR')
        if rk == 'FZ_RET_VOID':
            o.append('    case %d: %s; return 0;' % (i, call))
        elif rk == 'FZ_RET_PTR':
            o.append('    case %d: return %s != NULL;' % (i, call))
        else:
            o.append('    case %d: return (uint64_t)%s;' % (i, call))
    o.append('    default: return 0;')
    o.append('    }')
    o.append('}')
    o.append('#endif')
    with open(a.out, 'w') as f:
        f.write('\n'.join(o) + '\n')


if __name__ == '__main__':
    main()
