// compat/user_first.h — how an alias in the normal headers steps aside for a program's own
// function of the same name.
//
// Some alternate names (save_canvas_pgm, the 7-argument draw_line_f, vec3_normalize,
// mat4_perspective, create_cube) are also names programs give their OWN helpers, with
// slightly different signatures (char * for const char *, double for float, a static
// function, one declared in the program's header and defined in another file). Such a
// program must compile, link and call its own function. Two C++ rules make that so; each
// alias uses one of them, and documentation/compat.md says which:
//
//  * The alias is a function template, `template <class = void>`, with ordinary parameter
//    types. Where a program's function and the template's specialisation are equally
//    good matches, the non-template wins; a template is never a redeclaration of the
//    program's function, so even an identical signature with another result type
//    compiles, and the mangled names differ, so nothing clashes at link time. Pointer
//    parameters point to const where the alias only reads (const canvas_t *,
//    const char *), so a program's function taking non-const pointers is the better
//    match rather than an ambiguous one. Used where only pointer and struct arguments
//    are involved; the address can be taken as a plain function pointer.
//  * The alias's parameters are `fallback<T>`: every argument reaches them through a
//    user-defined conversion, which ranks below every standard conversion. So any
//    program function of that name that accepts the arguments at all (float, double or
//    int parameters, const or non-const canvas) is the better match for every argument.
//    Used where a program's own parameter could be a better match than the alias's on
//    some arguments and a worse one on others (float arguments passed to a program's
//    double parameters), which would make the call ambiguous. The price: the alias's
//    address cannot be taken as a plain function pointer.
//
// Int, float and double literals all reach a fallback<float> (one standard conversion to
// float, then the constructor), as they reach a plain float parameter.
#ifndef TINY3D_COMPAT_USER_FIRST_H
#define TINY3D_COMPAT_USER_FIRST_H

namespace tiny3d::compat {

template <class T>
struct fallback {
    T value;
    fallback(T v) : value(v) {}  // implicit on purpose: that conversion is the mechanism
};

}  // namespace tiny3d::compat

#endif
