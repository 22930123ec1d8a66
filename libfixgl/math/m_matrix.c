/* placeholder: filled in by the foundation work */
typedef int fgl_placeholder_math_m_matrix_c;
