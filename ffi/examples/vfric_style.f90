! A friction routine shaped like a finite-element code's user subroutine
! (Abaqus's VFRIC/FRIC style): per contact point, the normal pressure in,
! the friction coefficient out, from a curve built once on the first call.
! The driver program below calls it for a few contact points and checks
! the results against direct integration (kef_model_mu).
!
!   gfortran -O2 ffi/fortran/ke_friction.f90 ffi/examples/vfric_style.f90 \
!       -L target/release -lkefriction -Wl,-rpath,target/release -o vfric && ./vfric
module surface_friction
  use ke_friction
  implicit none
  private
  public :: friction_coefficient, hardness, nominal_to_fstar

  ! The surface pair (one per analysis): steel on steel, see the README.
  real(c_double), parameter :: psi = 5.6745d0, theta = 0.0015d0
  ! Hardness of the softer material, Pa: F* = p / H for a nominal pressure p.
  real(c_double), parameter :: hardness = 2.0d9

contains

  pure function nominal_to_fstar(pressure) result(f_star)
    real(c_double), intent(in) :: pressure
    real(c_double) :: f_star
    f_star = pressure / hardness
  end function

  ! Per contact point: pressure (Pa) in; mu out; status 0, or a KEF_ERR_*
  ! code (the caller decides: cut back the increment, or stop).
  subroutine friction_coefficient(npoints, pressure, mu, status)
    integer, intent(in) :: npoints
    real(c_double), intent(in) :: pressure(npoints)
    real(c_double), intent(out) :: mu(npoints)
    integer, intent(out) :: status
    type(c_ptr), save :: curve
    logical, save :: built = .false.
    integer :: k

    if (.not. built) then
      curve = kef_curve_from_model(psi, theta, 0.04d0, 0.3d0, 0.004d0, 1d-5, 0.1d0)
      if (.not. c_associated(curve)) then
        print '(a)', 'friction_coefficient: ' // kef_error_message()
        status = KEF_ERR_ARGUMENT
        return
      end if
      built = .true.
    end if
    status = KEF_OK
    do k = 1, npoints
      status = kef_curve_mu(curve, nominal_to_fstar(pressure(k)), mu(k))
      if (status /= KEF_OK) then
        print '(a, i0, a)', 'friction_coefficient: point ', k, ': ' // kef_error_message()
        return
      end if
    end do
  end subroutine
end module surface_friction

program vfric_driver
  use ke_friction
  use surface_friction
  implicit none
  real(c_double) :: pressure(4) = [2d5, 2d6, 2d7, 1.5d8]
  real(c_double) :: mu(4), exact
  integer :: status, k

  call friction_coefficient(4, pressure, mu, status)
  if (status /= KEF_OK) stop 1
  ! A second increment reuses the curve.
  call friction_coefficient(4, pressure, mu, status)
  if (status /= KEF_OK) stop 1
  do k = 1, 4
    if (kef_model_mu(5.6745d0, 0.0015d0, 0.04d0, 0.3d0, 0.004d0, nominal_to_fstar(pressure(k)), exact) /= KEF_OK) stop 2
    print '(a, es10.3, a, f10.7, a, es9.2)', 'p = ', pressure(k), ' Pa: mu = ', mu(k), &
        ', relative error ', abs(mu(k) / exact - 1)
    if (abs(mu(k) / exact - 1) > 1d-6) stop 3
  end do
  ! A pressure above the curve's range (F* > 0.1) is an error, not a crash.
  call friction_coefficient(1, [5d8], mu, status)
  if (status /= KEF_ERR_DOMAIN) stop 4
  print '(a)', 'vfric_style: ok'
end program vfric_driver
