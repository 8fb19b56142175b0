! ke_friction: Fortran interfaces to the C API of ke-friction
! (ffi/include/kefriction.h). Same names as the C functions; handles are
! type(c_ptr); scalars are passed by value, outputs by reference.
! Link with -lkefriction (or libkefriction.a -lpthread -ldl -lm).
! ffi/install.sh PREFIX installs it compiled (PREFIX/include/ke_friction.mod,
! PREFIX/lib/libkefriction_fortran.a; pkg-config kefriction-fortran).
!
! Every function returns KEF_OK or a KEF_ERR_* code (or c_null_ptr for a
! handle); kef_error_message() returns this thread's last message. The
! *_batch_nan functions write NaN at bad elements and count them in n_nan.
! Model constants: a handle from kef_constants_new (c_null_ptr where a
! function takes one: the defaults); names via kef_c_string("as-printed").
module ke_friction
  use, intrinsic :: iso_c_binding, only: c_int, c_int64_t, c_double, c_size_t, c_ptr, c_char, c_null_char, c_associated, c_f_pointer
  implicit none
  private
  public :: kef_table_default, kef_table_load, kef_table_free, kef_table_mu, kef_table_mu_with_slope, &
            kef_table_mu_batch, kef_table_mu_batch_nan, kef_table_mu_with_slope_batch, &
            kef_table_mu_with_slope_batch_nan, kef_curve_from_table, kef_curve_from_model, &
            kef_curve_from_model_with, kef_curve_mu, kef_curve_mu_with_slope, kef_curve_mu_batch, &
            kef_curve_mu_batch_nan, kef_curve_mu_with_slope_batch, kef_curve_mu_with_slope_batch_nan, &
            kef_curve_range, kef_curve_free, kef_model_mu, kef_model_mu_with, &
            kef_constants_new, kef_constants_free, kef_constants_set_beta, kef_constants_set_nu, &
            kef_constants_set_eps_star, kef_constants_set_fit, kef_constants_set_model, &
            kef_constants_beta, kef_constants_nu, kef_constants_eps_star, kef_constants_fit, &
            kef_constants_model, kef_constants_set_distribution, kef_constants_set_distribution_named, &
            kef_constants_set_heights, &
            kef_constants_distribution, kef_last_error, kef_error_message, kef_c_string, &
            kef_version, kef_version_string, kef_table_domain, kef_table_h_star, kef_table_h_star_batch, &
            kef_params_from_physical, kef_warnings, kef_clear_warnings, kef_warning_message, &
            kef_warning_text, &
            kef_law_new, kef_law_from_physical, kef_law_mu, &
            kef_law_mu_and_derivative, kef_law_mu_batch, kef_law_mu_batch_nan, &
            kef_law_mu_and_derivative_batch, kef_law_mu_and_derivative_batch_nan, kef_law_clamped, &
            kef_law_range, kef_law_max_error, kef_law_free, kef_law_from_props, kef_table_mu_with, &
            kef_table_mu_batch_with, kef_law_from_surface, kef_curve_from_table_with
  public :: c_int, c_double, c_size_t, c_ptr, c_associated, c_int64_t

  integer(c_int), parameter, public :: KEF_OK = 0
  integer(c_int), parameter, public :: KEF_ERR_DOMAIN = 1
  integer(c_int), parameter, public :: KEF_ERR_ARGUMENT = 2
  integer(c_int), parameter, public :: KEF_ERR_IO = 3
  integer(c_int), parameter, public :: KEF_ERR_TABLE = 4
  integer(c_int), parameter, public :: KEF_ERR_INTERNAL = 5
  integer(c_int), parameter, public :: KEF_ERR_NO_MU = 6
  ! Height distribution families (kef_constants_set_distribution,
  ! kef_constants_distribution).
  integer(c_int), parameter, public :: KEF_DIST_GAUSSIAN = 0
  integer(c_int), parameter, public :: KEF_DIST_PEARSON = 1
  integer(c_int), parameter, public :: KEF_DIST_WEIBULL = 2
  integer(c_int), parameter, public :: KEF_DIST_EMPIRICAL = 3
  ! Warning bits (kef_warnings, kef_warning_message): the core's kinds.
  integer(c_int), parameter, public :: KEF_WARN_F_STAR_BELOW_RANGE = 1
  integer(c_int), parameter, public :: KEF_WARN_F_STAR_ABOVE_RANGE = 2
  integer(c_int), parameter, public :: KEF_WARN_NEGATIVE_SEPARATION = 4
  integer(c_int), parameter, public :: KEF_WARN_ADHESION_DOMINATED = 8
  integer(c_int), parameter, public :: KEF_WARN_FEW_ASPERITIES = 16
  integer(c_int), parameter, public :: KEF_WARN_NON_PERIODIC = 32
  integer(c_int), parameter, public :: KEF_WARN_LOW_BANDWIDTH = 64
  integer(c_int), parameter, public :: KEF_WARN_ANISOTROPY = 128
  integer(c_int), parameter, public :: KEF_WARN_INTERVAL_MISMATCH = 256
  integer(c_int), parameter, public :: KEF_WARN_UNRELIABLE_SCALE = 512
  ! A friction law's policy outside its pressure range (kef_law_new).
  integer(c_int), parameter, public :: KEF_LAW_CLAMP = 0
  integer(c_int), parameter, public :: KEF_LAW_ERROR = 1

  interface
    function kef_last_error() bind(c, name="kef_last_error")
      import :: c_ptr
      type(c_ptr) :: kef_last_error
    end function

    ! The warning bits of this thread's calls since kef_clear_warnings.
    function kef_warnings() bind(c, name="kef_warnings")
      import :: c_int
      integer(c_int) :: kef_warnings
    end function

    subroutine kef_clear_warnings() bind(c, name="kef_clear_warnings")
    end subroutine

    ! The latest warning of one kind (a KEF_WARN_* bit); kef_warning_text(kind) as a Fortran string.
    function kef_warning_message(kind) bind(c, name="kef_warning_message")
      import :: c_ptr, c_int
      integer(c_int), value :: kind
      type(c_ptr) :: kef_warning_message
    end function

    ! A static C string (not to free); kef_version_string() as a Fortran string.
    function kef_version() bind(c, name="kef_version")
      import :: c_ptr
      type(c_ptr) :: kef_version
    end function

    function kef_table_default() bind(c, name="kef_table_default")
      import :: c_ptr
      type(c_ptr) :: kef_table_default
    end function

    ! path: a NUL-terminated string, e.g. kef_c_string("table.kft").
    function kef_table_load(path) bind(c, name="kef_table_load")
      import :: c_ptr, c_char
      character(kind=c_char), dimension(*), intent(in) :: path
      type(c_ptr) :: kef_table_load
    end function

    subroutine kef_table_free(table) bind(c, name="kef_table_free")
      import :: c_ptr
      type(c_ptr), value :: table
    end subroutine

    function kef_table_mu(table, psi, theta, f_star, mu) bind(c, name="kef_table_mu")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: table
      real(c_double), value :: psi, theta, f_star
      real(c_double), intent(out) :: mu
      integer(c_int) :: kef_table_mu
    end function

    ! kef_table_mu that refuses constants other than the table's.
    function kef_table_mu_with(table, constants, psi, theta, f_star, mu) bind(c, name="kef_table_mu_with")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: table, constants
      real(c_double), value :: psi, theta, f_star
      real(c_double), intent(out) :: mu
      integer(c_int) :: kef_table_mu_with
    end function

    function kef_table_mu_batch_with(table, constants, n, psi, theta, f_star, mu) &
        bind(c, name="kef_table_mu_batch_with")
      import :: c_ptr, c_double, c_int, c_size_t
      type(c_ptr), value :: table, constants
      integer(c_size_t), value :: n
      real(c_double), dimension(*), intent(in) :: psi, theta, f_star
      real(c_double), dimension(*), intent(inout) :: mu
      integer(c_int) :: kef_table_mu_batch_with
    end function

    function kef_table_mu_with_slope(table, psi, theta, f_star, mu, dmu_df_star) &
        bind(c, name="kef_table_mu_with_slope")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: table
      real(c_double), value :: psi, theta, f_star
      real(c_double), intent(out) :: mu, dmu_df_star
      integer(c_int) :: kef_table_mu_with_slope
    end function

    function kef_table_mu_batch(table, n, psi, theta, f_star, mu) bind(c, name="kef_table_mu_batch")
      import :: c_ptr, c_double, c_int, c_size_t
      type(c_ptr), value :: table
      integer(c_size_t), value :: n
      real(c_double), dimension(*), intent(in) :: psi, theta, f_star
      real(c_double), dimension(*), intent(inout) :: mu
      integer(c_int) :: kef_table_mu_batch
    end function

    function kef_table_mu_batch_nan(table, n, psi, theta, f_star, mu, n_nan) bind(c, name="kef_table_mu_batch_nan")
      import :: c_ptr, c_double, c_int, c_size_t
      type(c_ptr), value :: table
      integer(c_size_t), value :: n
      real(c_double), dimension(*), intent(in) :: psi, theta, f_star
      real(c_double), dimension(*), intent(inout) :: mu
      integer(c_size_t), intent(out) :: n_nan
      integer(c_int) :: kef_table_mu_batch_nan
    end function

    function kef_table_mu_with_slope_batch(table, n, psi, theta, f_star, mu, dmu_df_star) &
        bind(c, name="kef_table_mu_with_slope_batch")
      import :: c_ptr, c_double, c_int, c_size_t
      type(c_ptr), value :: table
      integer(c_size_t), value :: n
      real(c_double), dimension(*), intent(in) :: psi, theta, f_star
      real(c_double), dimension(*), intent(inout) :: mu, dmu_df_star
      integer(c_int) :: kef_table_mu_with_slope_batch
    end function

    function kef_table_mu_with_slope_batch_nan(table, n, psi, theta, f_star, mu, dmu_df_star, n_nan) &
        bind(c, name="kef_table_mu_with_slope_batch_nan")
      import :: c_ptr, c_double, c_int, c_size_t
      type(c_ptr), value :: table
      integer(c_size_t), value :: n
      real(c_double), dimension(*), intent(in) :: psi, theta, f_star
      real(c_double), dimension(*), intent(inout) :: mu, dmu_df_star
      integer(c_size_t), intent(out) :: n_nan
      integer(c_int) :: kef_table_mu_with_slope_batch_nan
    end function

    function kef_table_domain(table, psi_min, psi_max, theta_min, theta_max, f_star_min, f_star_max) &
        bind(c, name="kef_table_domain")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: table
      real(c_double), intent(out) :: psi_min, psi_max, theta_min, theta_max, f_star_min, f_star_max
      integer(c_int) :: kef_table_domain
    end function

    function kef_table_h_star(table, psi, theta, f_star, h_star) bind(c, name="kef_table_h_star")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: table
      real(c_double), value :: psi, theta, f_star
      real(c_double), intent(out) :: h_star
      integer(c_int) :: kef_table_h_star
    end function

    function kef_table_h_star_batch(table, n, psi, theta, f_star, h_star) bind(c, name="kef_table_h_star_batch")
      import :: c_ptr, c_double, c_int, c_size_t
      type(c_ptr), value :: table
      integer(c_size_t), value :: n
      real(c_double), dimension(*), intent(in) :: psi, theta, f_star
      real(c_double), dimension(*), intent(inout) :: h_star
      integer(c_int) :: kef_table_h_star_batch
    end function

    ! SI inputs (material 1 the softer); outputs the model's psi, theta, beta, nu, eps_star.
    function kef_params_from_physical(e1, nu1, e2, nu2, hardness, sigma, radius, density, delta_gamma, epsilon, &
        psi, theta, beta, nu, eps_star) bind(c, name="kef_params_from_physical")
      import :: c_double, c_int
      real(c_double), value :: e1, nu1, e2, nu2, hardness, sigma, radius, density, delta_gamma, epsilon
      real(c_double), intent(out) :: psi, theta, beta, nu, eps_star
      integer(c_int) :: kef_params_from_physical
    end function

    function kef_curve_from_table(table, psi, theta) bind(c, name="kef_curve_from_table")
      import :: c_ptr, c_double
      type(c_ptr), value :: table
      real(c_double), value :: psi, theta
      type(c_ptr) :: kef_curve_from_table
    end function

    ! kef_curve_from_table that refuses constants other than the table's.
    function kef_curve_from_table_with(table, constants, psi, theta) bind(c, name="kef_curve_from_table_with")
      import :: c_ptr, c_double
      type(c_ptr), value :: table, constants
      real(c_double), value :: psi, theta
      type(c_ptr) :: kef_curve_from_table_with
    end function

    function kef_curve_from_model(psi, theta, beta, nu, eps_star, f_star_min, f_star_max) &
        bind(c, name="kef_curve_from_model")
      import :: c_ptr, c_double
      real(c_double), value :: psi, theta, beta, nu, eps_star, f_star_min, f_star_max
      type(c_ptr) :: kef_curve_from_model
    end function

    ! constants: from kef_constants_new, or c_null_ptr for the defaults.
    function kef_curve_from_model_with(constants, psi, theta, f_star_min, f_star_max) &
        bind(c, name="kef_curve_from_model_with")
      import :: c_ptr, c_double
      type(c_ptr), value :: constants
      real(c_double), value :: psi, theta, f_star_min, f_star_max
      type(c_ptr) :: kef_curve_from_model_with
    end function

    function kef_curve_mu(curve, f_star, mu) bind(c, name="kef_curve_mu")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: curve
      real(c_double), value :: f_star
      real(c_double), intent(out) :: mu
      integer(c_int) :: kef_curve_mu
    end function

    function kef_curve_mu_with_slope(curve, f_star, mu, dmu_df_star) bind(c, name="kef_curve_mu_with_slope")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: curve
      real(c_double), value :: f_star
      real(c_double), intent(out) :: mu, dmu_df_star
      integer(c_int) :: kef_curve_mu_with_slope
    end function

    function kef_curve_mu_batch(curve, n, f_star, mu) bind(c, name="kef_curve_mu_batch")
      import :: c_ptr, c_double, c_int, c_size_t
      type(c_ptr), value :: curve
      integer(c_size_t), value :: n
      real(c_double), dimension(*), intent(in) :: f_star
      real(c_double), dimension(*), intent(inout) :: mu
      integer(c_int) :: kef_curve_mu_batch
    end function

    function kef_curve_mu_batch_nan(curve, n, f_star, mu, n_nan) bind(c, name="kef_curve_mu_batch_nan")
      import :: c_ptr, c_double, c_int, c_size_t
      type(c_ptr), value :: curve
      integer(c_size_t), value :: n
      real(c_double), dimension(*), intent(in) :: f_star
      real(c_double), dimension(*), intent(inout) :: mu
      integer(c_size_t), intent(out) :: n_nan
      integer(c_int) :: kef_curve_mu_batch_nan
    end function

    function kef_curve_mu_with_slope_batch(curve, n, f_star, mu, dmu_df_star) &
        bind(c, name="kef_curve_mu_with_slope_batch")
      import :: c_ptr, c_double, c_int, c_size_t
      type(c_ptr), value :: curve
      integer(c_size_t), value :: n
      real(c_double), dimension(*), intent(in) :: f_star
      real(c_double), dimension(*), intent(inout) :: mu, dmu_df_star
      integer(c_int) :: kef_curve_mu_with_slope_batch
    end function

    function kef_curve_mu_with_slope_batch_nan(curve, n, f_star, mu, dmu_df_star, n_nan) &
        bind(c, name="kef_curve_mu_with_slope_batch_nan")
      import :: c_ptr, c_double, c_int, c_size_t
      type(c_ptr), value :: curve
      integer(c_size_t), value :: n
      real(c_double), dimension(*), intent(in) :: f_star
      real(c_double), dimension(*), intent(inout) :: mu, dmu_df_star
      integer(c_size_t), intent(out) :: n_nan
      integer(c_int) :: kef_curve_mu_with_slope_batch_nan
    end function

    function kef_curve_range(curve, f_star_min, f_star_max) bind(c, name="kef_curve_range")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: curve
      real(c_double), intent(out) :: f_star_min, f_star_max
      integer(c_int) :: kef_curve_range
    end function

    subroutine kef_curve_free(curve) bind(c, name="kef_curve_free")
      import :: c_ptr
      type(c_ptr), value :: curve
    end subroutine

    function kef_model_mu(psi, theta, beta, nu, eps_star, f_star, mu) bind(c, name="kef_model_mu")
      import :: c_double, c_int
      real(c_double), value :: psi, theta, beta, nu, eps_star, f_star
      real(c_double), intent(out) :: mu
      integer(c_int) :: kef_model_mu
    end function

    function kef_model_mu_with(constants, psi, theta, f_star, mu) bind(c, name="kef_model_mu_with")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: constants
      real(c_double), value :: psi, theta, f_star
      real(c_double), intent(out) :: mu
      integer(c_int) :: kef_model_mu_with
    end function

    function kef_constants_new() bind(c, name="kef_constants_new")
      import :: c_ptr
      type(c_ptr) :: kef_constants_new
    end function

    subroutine kef_constants_free(constants) bind(c, name="kef_constants_free")
      import :: c_ptr
      type(c_ptr), value :: constants
    end subroutine

    function kef_constants_set_beta(constants, beta) bind(c, name="kef_constants_set_beta")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: constants
      real(c_double), value :: beta
      integer(c_int) :: kef_constants_set_beta
    end function

    function kef_constants_set_nu(constants, nu) bind(c, name="kef_constants_set_nu")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: constants
      real(c_double), value :: nu
      integer(c_int) :: kef_constants_set_nu
    end function

    function kef_constants_set_eps_star(constants, eps_star) bind(c, name="kef_constants_set_eps_star")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: constants
      real(c_double), value :: eps_star
      integer(c_int) :: kef_constants_set_eps_star
    end function

    ! name: a NUL-terminated string, e.g. kef_c_string("as-printed").
    function kef_constants_set_fit(constants, name) bind(c, name="kef_constants_set_fit")
      import :: c_ptr, c_char, c_int
      type(c_ptr), value :: constants
      character(kind=c_char), dimension(*), intent(in) :: name
      integer(c_int) :: kef_constants_set_fit
    end function

    ! name: a NUL-terminated string, e.g. kef_c_string("ceb").
    function kef_constants_set_model(constants, name) bind(c, name="kef_constants_set_model")
      import :: c_ptr, c_char, c_int
      type(c_ptr), value :: constants
      character(kind=c_char), dimension(*), intent(in) :: name
      integer(c_int) :: kef_constants_set_model
    end function

    function kef_constants_beta(constants) bind(c, name="kef_constants_beta")
      import :: c_ptr, c_double
      type(c_ptr), value :: constants
      real(c_double) :: kef_constants_beta
    end function

    function kef_constants_nu(constants) bind(c, name="kef_constants_nu")
      import :: c_ptr, c_double
      type(c_ptr), value :: constants
      real(c_double) :: kef_constants_nu
    end function

    function kef_constants_eps_star(constants) bind(c, name="kef_constants_eps_star")
      import :: c_ptr, c_double
      type(c_ptr), value :: constants
      real(c_double) :: kef_constants_eps_star
    end function

    ! A static C string (not to free).
    function kef_constants_fit(constants) bind(c, name="kef_constants_fit")
      import :: c_ptr
      type(c_ptr), value :: constants
      type(c_ptr) :: kef_constants_fit
    end function

    ! A static C string (not to free).
    function kef_constants_model(constants) bind(c, name="kef_constants_model")
      import :: c_ptr
      type(c_ptr), value :: constants
      type(c_ptr) :: kef_constants_model
    end function

    ! family: KEF_DIST_GAUSSIAN (skewness, kurtosis ignored), KEF_DIST_PEARSON
    ! (kurtosis not excess: 3 for a Gaussian; K > Sk**2 + 1) or KEF_DIST_WEIBULL
    ! (kurtosis ignored: it follows from the skewness).
    function kef_constants_set_distribution(constants, family, skewness, kurtosis) &
        bind(c, name="kef_constants_set_distribution")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: constants
      integer(c_int), value :: family
      real(c_double), value :: skewness, kurtosis
      integer(c_int) :: kef_constants_set_distribution
    end function

    ! The family by name, e.g. kef_c_string("pearson"): "gaussian", "pearson", "weibull".
    function kef_constants_set_distribution_named(constants, family, skewness, kurtosis) &
        bind(c, name="kef_constants_set_distribution_named")
      import :: c_ptr, c_char, c_double, c_int
      type(c_ptr), value :: constants
      character(kind=c_char), dimension(*), intent(in) :: family
      real(c_double), value :: skewness, kurtosis
      integer(c_int) :: kef_constants_set_distribution_named
    end function

    ! An empirical density of n measured heights (copied; NaN skipped; >= 100 finite).
    function kef_constants_set_heights(constants, heights, n) bind(c, name="kef_constants_set_heights")
      import :: c_ptr, c_double, c_size_t, c_int
      type(c_ptr), value :: constants
      real(c_double), dimension(*), intent(in) :: heights
      integer(c_size_t), value :: n
      integer(c_int) :: kef_constants_set_heights
    end function

    ! family: a KEF_DIST_* code; kurtosis not excess.
    function kef_constants_distribution(constants, family, skewness, kurtosis) &
        bind(c, name="kef_constants_distribution")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: constants
      integer(c_int), intent(out) :: family
      real(c_double), intent(out) :: skewness, kurtosis
      integer(c_int) :: kef_constants_distribution
    end function

    function c_strlen(s) bind(c, name="strlen")
      import :: c_ptr, c_size_t
      type(c_ptr), value :: s
      integer(c_size_t) :: c_strlen
    end function

    ! A friction law mu(p), dmu/dp of the contact pressure p in Pa:
    ! p_min = p_max = 0 for the default range 1e-5*H to 0.1*H; policy
    ! KEF_LAW_CLAMP or KEF_LAW_ERROR.
    function kef_law_new(constants, psi, theta, hardness, p_min, p_max, policy) bind(c, name="kef_law_new")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: constants
      real(c_double), value :: psi, theta, hardness, p_min, p_max
      integer(c_int), value :: policy
      type(c_ptr) :: kef_law_new
    end function

    function kef_law_from_physical(e1, nu1, e2, nu2, hardness, sigma, radius, density, delta_gamma, epsilon, &
        p_min, p_max, policy) bind(c, name="kef_law_from_physical")
      import :: c_ptr, c_double, c_int
      real(c_double), value :: e1, nu1, e2, nu2, hardness, sigma, radius, density, delta_gamma, epsilon
      real(c_double), value :: p_min, p_max
      integer(c_int), value :: policy
      type(c_ptr) :: kef_law_from_physical
    end function

    ! path, family: NUL-terminated, e.g. kef_c_string("surface.x3p"),
    ! kef_c_string("pearson") (kef_c_string(""): the default family).
    function kef_law_from_surface(path, family, e1, nu1, e2, nu2, hardness, delta_gamma, epsilon, &
        p_min, p_max, policy) bind(c, name="kef_law_from_surface")
      import :: c_ptr, c_double, c_int, c_char
      character(kind=c_char), dimension(*), intent(in) :: path, family
      real(c_double), value :: e1, nu1, e2, nu2, hardness, delta_gamma, epsilon, p_min, p_max
      integer(c_int), value :: policy
      type(c_ptr) :: kef_law_from_surface
    end function

    function kef_law_mu(law, p, mu) bind(c, name="kef_law_mu")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: law
      real(c_double), value :: p
      real(c_double), intent(out) :: mu
      integer(c_int) :: kef_law_mu
    end function

    function kef_law_mu_and_derivative(law, p, mu, dmu_dp) bind(c, name="kef_law_mu_and_derivative")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: law
      real(c_double), value :: p
      real(c_double), intent(out) :: mu, dmu_dp
      integer(c_int) :: kef_law_mu_and_derivative
    end function

    function kef_law_mu_batch(law, n, p, mu) bind(c, name="kef_law_mu_batch")
      import :: c_ptr, c_double, c_int, c_size_t
      type(c_ptr), value :: law
      integer(c_size_t), value :: n
      real(c_double), dimension(*), intent(in) :: p
      real(c_double), dimension(*), intent(inout) :: mu
      integer(c_int) :: kef_law_mu_batch
    end function

    function kef_law_mu_batch_nan(law, n, p, mu, n_nan) bind(c, name="kef_law_mu_batch_nan")
      import :: c_ptr, c_double, c_int, c_size_t
      type(c_ptr), value :: law
      integer(c_size_t), value :: n
      real(c_double), dimension(*), intent(in) :: p
      real(c_double), dimension(*), intent(inout) :: mu
      integer(c_size_t), intent(out) :: n_nan
      integer(c_int) :: kef_law_mu_batch_nan
    end function

    function kef_law_mu_and_derivative_batch(law, n, p, mu, dmu_dp) bind(c, name="kef_law_mu_and_derivative_batch")
      import :: c_ptr, c_double, c_int, c_size_t
      type(c_ptr), value :: law
      integer(c_size_t), value :: n
      real(c_double), dimension(*), intent(in) :: p
      real(c_double), dimension(*), intent(inout) :: mu, dmu_dp
      integer(c_int) :: kef_law_mu_and_derivative_batch
    end function

    function kef_law_mu_and_derivative_batch_nan(law, n, p, mu, dmu_dp, n_nan) &
        bind(c, name="kef_law_mu_and_derivative_batch_nan")
      import :: c_ptr, c_double, c_int, c_size_t
      type(c_ptr), value :: law
      integer(c_size_t), value :: n
      real(c_double), dimension(*), intent(in) :: p
      real(c_double), dimension(*), intent(inout) :: mu, dmu_dp
      integer(c_size_t), intent(out) :: n_nan
      integer(c_int) :: kef_law_mu_and_derivative_batch_nan
    end function

    ! reset /= 0 sets the count to 0 as it reads it.
    function kef_law_clamped(law, reset, count) bind(c, name="kef_law_clamped")
      import :: c_ptr, c_int, c_int64_t
      type(c_ptr), value :: law
      integer(c_int), value :: reset
      integer(c_int64_t), intent(out) :: count
      integer(c_int) :: kef_law_clamped
    end function

    function kef_law_range(law, p_min, p_max, hardness) bind(c, name="kef_law_range")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: law
      real(c_double), intent(out) :: p_min, p_max, hardness
      integer(c_int) :: kef_law_range
    end function

    function kef_law_max_error(law) bind(c, name="kef_law_max_error")
      import :: c_ptr, c_double
      type(c_ptr), value :: law
      real(c_double) :: kef_law_max_error
    end function

    ! A law shared for the life of the process, built once per distinct
    ! props (psi, theta, H[, p_min, p_max[, beta, nu, eps_star]]): not to free.
    function kef_law_from_props(n_props, props) bind(c, name="kef_law_from_props")
      import :: c_ptr, c_double, c_size_t
      integer(c_size_t), value :: n_props
      real(c_double), dimension(*), intent(in) :: props
      type(c_ptr) :: kef_law_from_props
    end function

    subroutine kef_law_free(law) bind(c, name="kef_law_free")
      import :: c_ptr
      type(c_ptr), value :: law
    end subroutine
  end interface

contains

  ! This thread's last failure message, as a Fortran string ("" if none).
  function kef_error_message() result(message)
    character(len=:), allocatable :: message
    message = f_string(kef_last_error())
  end function

  ! The latest warning of kind `kind` (a KEF_WARN_* bit) on this thread, as a Fortran string ("" if none).
  function kef_warning_text(kind) result(message)
    integer(c_int), intent(in) :: kind
    character(len=:), allocatable :: message
    message = f_string(kef_warning_message(kind))
  end function

  ! The library's version ("MAJOR.MINOR.PATCH"), as a Fortran string.
  function kef_version_string() result(version)
    character(len=:), allocatable :: version
    version = f_string(kef_version())
  end function

  ! A NUL-terminated C string as a Fortran string.
  function f_string(p) result(message)
    type(c_ptr), intent(in) :: p
    character(len=:), allocatable :: message
    character(kind=c_char), pointer :: chars(:)
    integer :: i, n
    n = int(c_strlen(p))
    allocate(character(len=n) :: message)
    if (n == 0) return
    call c_f_pointer(p, chars, [n])
    do i = 1, n
      message(i:i) = chars(i)
    end do
  end function

  ! A Fortran string as a NUL-terminated C string (for kef_table_load).
  function kef_c_string(text) result(c_text)
    character(len=*), intent(in) :: text
    character(kind=c_char, len=len_trim(text) + 1) :: c_text
    c_text = trim(text) // c_null_char
  end function
end module ke_friction
