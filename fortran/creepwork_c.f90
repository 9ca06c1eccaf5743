! The C header creepwork/creepwork.h as Fortran sees it, generated from the
! header at build time so that the two cannot drift:
!   creepwork_types  every status code and #define as a named constant and
!                    every struct as a bind(C) derived type; module
!                    creepwork makes all of it public
!   creepwork_capi   every CW_API function cw_x as a bind(C) interface capi_x,
!                    for the library's own modules only: callers use the
!                    wrappers of module creepwork
! (generate_interfaces.py writes both.) tests/fortran/check_fortran_bindings.py
! checks that every interface is wrapped by module creepwork.

module creepwork_types
   use, intrinsic :: iso_c_binding, only: c_int, c_size_t, c_double, c_int64_t, c_char, c_null_char, &
                                          c_ptr, c_null_ptr
   implicit none
   private

   include 'creepwork_constants.inc'
   include 'creepwork_types.inc'
end module creepwork_types

module creepwork_capi
   use, intrinsic :: iso_c_binding, only: c_int, c_size_t, c_double, c_int64_t, c_char, c_ptr
   use creepwork_types
   implicit none

   include 'creepwork_bindings.inc'

   interface
      ! From the C library: length of a NUL-terminated string.
      pure function c_strlen(s) bind(c, name='strlen') result(n)
         import :: c_ptr, c_size_t
         type(c_ptr), value :: s
         integer(c_size_t) :: n
      end function c_strlen
   end interface
end module creepwork_capi
