! Many contacts of one surface pair from Fortran: a curve built once,
! looked up in the inner loop; prints a few mu values and the time per lookup.
!
!   gfortran -O2 -I build ffi/fortran/ke_friction.f90 ffi/examples/contacts.f90 \
!       -L target/release -lkefriction -Wl,-rpath,target/release -o contacts_f
program contacts
  use ke_friction
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  implicit none
  integer, parameter :: n = 100000, rounds = 21
  real(c_double), parameter :: psi = 1.0d0, theta = 0.003d0
  real(c_double) :: loads(4) = [1d-4, 1d-3, 1d-2, 5d-2]
  real(c_double), allocatable :: f(:), mu(:)
  real(c_double) :: m, slope, times(rounds), t
  type(c_ptr) :: curve, constants
  real(c_double) :: few(3) = [1d-3, 0.5d0, 1d-2], out(3)
  integer(c_size_t) :: n_nan
  integer(c_int) :: family
  real(c_double) :: sk, ku
  integer :: i, r
  integer(8) :: t0, t1, rate

  curve = kef_curve_from_table(kef_table_default(), psi, theta)
  if (.not. c_associated(curve)) then
    print '(a)', 'kef_curve_from_table: ' // kef_error_message()
    stop 1
  end if
  do i = 1, 4
    if (kef_curve_mu_with_slope(curve, loads(i), m, slope) /= KEF_OK) then
      print '(a)', kef_error_message()
      stop 1
    end if
    print '(a, es24.17, a, es24.17)', 'mu f_star=', loads(i), ' mu=', m
  end do
  if (kef_curve_mu(curve, 0.5d0, m) /= KEF_ERR_DOMAIN) stop 2
  print '(a)', 'expected error: ' // kef_error_message()
  ! A batch that does not stop: NaN at the load outside the range.
  if (kef_curve_mu_batch_nan(curve, 3_c_size_t, few, out, n_nan) /= KEF_OK) stop 4
  if (n_nan /= 1 .or. .not. ieee_is_nan(out(2)) .or. out(1) <= 0 .or. out(3) <= 0) stop 4
  ! Model constants: the printed fit, and a beta out of range refused.
  constants = kef_constants_new()
  if (kef_constants_set_fit(constants, kef_c_string("as-printed")) /= KEF_OK) stop 5
  if (kef_constants_set_beta(constants, 0.01d0) /= KEF_ERR_DOMAIN) stop 5
  print '(a)', 'expected error: ' // kef_error_message()
  if (kef_model_mu_with(constants, psi, theta, 1d-2, m) /= KEF_OK) stop 5
  print '(a, f10.7)', 'mu with the printed fit at f_star = 0.01: ', m
  ! Peaked heights: the Pearson distribution of skewness 0 and kurtosis 8
  ! (mu = 0.2529016383 at psi = 1, theta = 0.001, F* = 1e-4); a pair with
  ! kurtosis <= skewness**2 + 1 refused.
  if (kef_constants_set_distribution(constants, KEF_DIST_PEARSON, 0d0, 8d0) /= KEF_OK) stop 6
  if (kef_constants_set_distribution(constants, KEF_DIST_PEARSON, 0.5d0, 1.2d0) /= KEF_ERR_DOMAIN) stop 6
  print '(a)', 'expected error: ' // kef_error_message()
  if (kef_constants_distribution(constants, family, sk, ku) /= KEF_OK) stop 6
  if (family /= KEF_DIST_PEARSON .or. sk /= 0d0 .or. ku /= 8d0) stop 6
  if (kef_constants_set_fit(constants, kef_c_string("consistent")) /= KEF_OK) stop 6
  if (kef_model_mu_with(constants, 1d0, 1d-3, 1d-4, m) /= KEF_OK) stop 6
  if (abs(m - 0.2529016383d0) > 1d-9) stop 6
  print '(a, f12.10)', 'mu with Pearson(0, 8) heights at f_star = 1e-4: ', m
  call kef_constants_free(constants)

  allocate(f(n), mu(n))
  do i = 1, n
    f(i) = 1d-5 * 1d4 ** (real(i - 1, c_double) / n)
  end do
  call system_clock(count_rate=rate)
  do r = 1, rounds
    call system_clock(t0)
    do i = 1, n
      if (kef_curve_mu(curve, f(i), mu(i)) /= KEF_OK) stop 3
    end do
    call system_clock(t1)
    times(r) = real(t1 - t0, c_double) / rate / n * 1d9
  end do
  ! Median by insertion sort.
  do r = 2, rounds
    t = times(r)
    i = r - 1
    do while (i >= 1)
      if (times(i) <= t) exit
      times(i + 1) = times(i)
      i = i - 1
    end do
    times(i + 1) = t
  end do
  print '(a, i0, a, f6.2, a)', 'time per lookup (median of ', rounds, ' rounds): kef_curve_mu ', &
      times((rounds + 1) / 2), ' ns'
  call kef_curve_free(curve)
end program contacts
