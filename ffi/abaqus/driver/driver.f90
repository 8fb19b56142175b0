! Calls ffi/abaqus/fric_coef.f as Abaqus/Standard does (CI: .ci/ffi.sh):
! blocks of contact nodes, two materials (two props lists: 3 and 8
! values), from several OpenMP threads at once, with the stand-in
! ABA_PARAM.INC of this folder. Checks, for every node:
! - mu and dmu/dp against the library's law built directly (kef_law_new,
!   the same inputs, policy clamp), to 1e-12 relative;
! - dmu/dp against a central difference of FRIC_COEF's own mu (steps of
!   1e-6*p; inside the pressure range), to 1e-5 relative;
! - open nodes (p <= 0): mu at p_min, derivative 0;
! - p = +inf: mu at p_max (clamped as 1e300 is), derivative 0; a NaN
!   pressure: mu NaN (issue 46);
! - every other entry of fCoefDeriv 0 (columns 1, 3 to 20 of the first
!   slice and all of the second: the array comes in filled with -7), and
!   fCoef(:,2) as it came in (-5: the second direction is not written);
! - one shared law per props list (kef_law_from_props gives one pointer).
! With the argument "bad": props of a wrong length, which must stop the
! analysis through XIT (this stand-in: exit status 3) with the message.
program fric_coef_driver
  use ke_friction
  use, intrinsic :: iso_c_binding, only: c_null_ptr
  use omp_lib, only: omp_get_max_threads, omp_get_thread_num
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf, ieee_quiet_nan, ieee_is_nan
  implicit none
  integer, parameter :: n_block = 37, n_blocks = 96
  real(c_double), parameter :: value_tol = 1d-12, slope_tol = 1d-5, step = 1d-6
  real(c_double) :: props_a(3), props_b(8), worst_value, worst_slope, p_lo, p_hi, h
  type(c_ptr) :: reference(2), constants
  integer :: b, n_bad, threads_seen, arg_len
  character(len=16) :: arg
  integer(c_int) :: code

  ! Material A: psi = 1, theta = 0.001, H = 1 GPa, the default range.
  props_a = [1d0, 1d-3, 1d9]
  ! Material B: psi = 2.5, theta = 0.003, H = 2 GPa, p in [1e5, 1e8] Pa,
  ! beta = 0.05, nu = 0.33, eps_star = 0.006.
  props_b = [2.5d0, 3d-3, 2d9, 1d5, 1d8, 0.05d0, 0.33d0, 6d-3]

  call get_command_argument(1, arg, arg_len)
  if (arg == 'bad') then
    call bad_props()
    stop 'driver: FRIC_COEF did not stop on bad props'
  end if

  reference(1) = kef_law_new(c_null_ptr, 1d0, 1d-3, 1d9, 0d0, 0d0, KEF_LAW_CLAMP)
  constants = kef_constants_new()
  code = kef_constants_set_beta(constants, 0.05d0)
  code = code + kef_constants_set_nu(constants, 0.33d0)
  code = code + kef_constants_set_eps_star(constants, 6d-3)
  reference(2) = kef_law_new(constants, 2.5d0, 3d-3, 2d9, 1d5, 1d8, KEF_LAW_CLAMP)
  if (code /= KEF_OK .or. .not. c_associated(reference(1)) .or. .not. c_associated(reference(2))) then
    print '(2a)', 'driver: ', kef_error_message()
    error stop 1
  end if

  worst_value = 0
  worst_slope = 0
  n_bad = 0
  threads_seen = 0
  !$omp parallel do schedule(dynamic, 1) reduction(max: worst_value, worst_slope, threads_seen) &
  !$omp& reduction(+: n_bad)
  do b = 1, n_blocks
    threads_seen = max(threads_seen, omp_get_thread_num() + 1)
    if (mod(b, 2) == 1) then
      call one_block(b, props_a, reference(1), worst_value, worst_slope, n_bad)
    else
      call one_block(b, props_b, reference(2), worst_value, worst_slope, n_bad)
    end if
  end do
  !$omp end parallel do

  ! One shared law per props list.
  if (.not. c_same(kef_law_from_props(3_c_size_t, props_a), kef_law_from_props(3_c_size_t, props_a))) then
    n_bad = n_bad + 1
    print '(a)', 'driver: kef_law_from_props built props A twice'
  end if
  code = kef_law_range(kef_law_from_props(8_c_size_t, props_b), p_lo, p_hi, h)
  if (code /= KEF_OK .or. p_lo /= 1d5 .or. p_hi /= 1d8 .or. h /= 2d9) n_bad = n_bad + 1

  print '(a,i0,a,i0,a,i0,a)', 'fric_coef: ', n_blocks, ' blocks of ', n_block, ' nodes on ', threads_seen, ' threads'
  print '(a,es9.2,a,es9.2,a)', 'fric_coef: mu and dmu/dp within ', worst_value, &
    ' of the library; dmu/dp within ', worst_slope, ' of a central difference'
  call kef_law_free(reference(1))
  call kef_law_free(reference(2))
  call kef_constants_free(constants)
  if (n_bad > 0 .or. worst_value > value_tol .or. worst_slope > slope_tol .or. threads_seen < 2 &
      .and. omp_get_max_threads() > 1) then
    print '(a,i0,a)', 'fric_coef: FAILED (', n_bad, ' bad nodes)'
    error stop 1
  end if
  print '(a)', 'fric_coef: ok'

contains

  logical function c_same(a, b)
    type(c_ptr), intent(in) :: a, b
    c_same = c_associated(a, b)
  end function

  ! One block: pressures log-spaced over the range and beyond it, two open
  ! nodes; FRIC_COEF at p, p(1 + step), p(1 - step).
  subroutine one_block(b, props, law, worst_value, worst_slope, n_bad)
    integer, intent(in) :: b
    real(c_double), intent(in) :: props(:)
    type(c_ptr), intent(in) :: law
    real(c_double), intent(inout) :: worst_value, worst_slope
    integer, intent(inout) :: n_bad
    real(c_double) :: p(n_block), up(n_block), down(n_block)
    real(c_double) :: mu(n_block, 2), d(n_block, 20, 2), mu_up(n_block, 2), mu_down(n_block, 2), scratch(n_block, 20, 2)
    real(c_double) :: want_mu, want_d, lo, hi, hard, mu_lo, mu_hi, fd
    integer :: k
    integer(c_int) :: code
    code = kef_law_range(law, lo, hi, hard)
    do k = 1, n_block
      ! From lo/3 to 3*hi, shifted per block.
      p(k) = (lo / 3) * (9 * hi / lo)**((k - 1 + 0.37d0 * mod(b, 7)) / (n_block + 2))
    end do
    p(5) = 0
    p(n_block - 3) = -1d3
    p(n_block - 1) = ieee_value(1d0, ieee_positive_inf)
    p(n_block) = ieee_value(1d0, ieee_quiet_nan)
    up = p * (1 + step)
    down = p * (1 - step)
    call call_fric_coef(props, p, mu, d)
    if (any(mu(:, 2) /= -5)) n_bad = n_bad + 1
    call call_fric_coef(props, up, mu_up, scratch)
    call call_fric_coef(props, down, mu_down, scratch)
    code = kef_law_mu(law, lo, mu_lo)
    code = kef_law_mu(law, hi, mu_hi)
    do k = 1, n_block
      if (d(k, 1, 1) /= 0 .or. any(d(k, 3:20, 1) /= 0) .or. any(d(k, :, 2) /= 0)) n_bad = n_bad + 1
      if (mu(k, 2) /= -5) n_bad = n_bad + 1
      if (ieee_is_nan(p(k))) then
        if (.not. ieee_is_nan(mu(k, 1))) n_bad = n_bad + 1
        cycle
      end if
      if (p(k) > huge(p(k))) then
        if (mu(k, 1) /= mu_hi .or. d(k, 2, 1) /= 0) n_bad = n_bad + 1
        cycle
      end if
      if (p(k) <= 0) then
        if (mu(k, 1) /= mu_lo .or. d(k, 2, 1) /= 0) n_bad = n_bad + 1
        cycle
      end if
      code = kef_law_mu_and_derivative(law, p(k), want_mu, want_d)
      if (code /= KEF_OK) then
        n_bad = n_bad + 1
        cycle
      end if
      worst_value = max(worst_value, abs(mu(k, 1) / want_mu - 1))
      if (want_d /= 0) then
        worst_value = max(worst_value, abs(d(k, 2, 1) / want_d - 1))
      else if (d(k, 2, 1) /= 0) then
        n_bad = n_bad + 1
      end if
      if (down(k) > lo .and. up(k) < hi) then
        fd = (mu_up(k, 1) - mu_down(k, 1)) / (up(k) - down(k))
        worst_slope = max(worst_slope, abs(fd / d(k, 2, 1) - 1))
      end if
    end do
  end subroutine

  ! FRIC_COEF with the arguments Abaqus passes (those the law does not
  ! read filled with what Abaqus would give).
  subroutine call_fric_coef(props, pressure, f_coef, f_coef_deriv)
    real(c_double), intent(in) :: props(:), pressure(n_block)
    real(c_double), intent(inout) :: f_coef(n_block, 2), f_coef_deriv(n_block, 20, 2)
    real(c_double) :: slip_data(n_block, 6), temp_avg(n_block), field_avg(n_block, 1), r_data(8)
    integer :: i_data(6)
    character(len=80) :: surf_int, surf_sec, surf_main
    external fric_coef
    slip_data = 0
    temp_avg = 20
    field_avg = 0
    r_data = 0
    i_data = [1, 1, 1, 0, 0, 1]
    surf_int = 'KE-FRICTION'
    surf_sec = 'SECONDARY'
    surf_main = 'MAIN'
    ! What the routine must overwrite, and what it must leave.
    f_coef(:, 1) = 0
    f_coef(:, 2) = -5
    f_coef_deriv = -7
    call fric_coef(f_coef, f_coef_deriv, n_block, size(props), 1, 0, i_data, r_data, surf_int, surf_sec, &
                   surf_main, props, slip_data, pressure, temp_avg, field_avg)
  end subroutine

  subroutine bad_props()
    real(c_double) :: p(n_block), mu(n_block, 2), d(n_block, 20, 2)
    p = 1d6
    call call_fric_coef([1d0, 1d-3, 1d9, 1d4], p, mu, d)
  end subroutine
end program

! Abaqus' XIT (terminate the analysis), stood in for: exit status 3.
subroutine xit()
  stop 3
end subroutine
