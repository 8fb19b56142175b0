C ke-friction's friction law as an Abaqus/Standard FRIC_COEF user
C subroutine: mu of the contact pressure at each node of a block, and
C dmu/dp for the Jacobian, from the Kogut-Etsion model (libkefriction).
C
C Link: abaqus job=JOB user=fric_coef.f with libkefriction on the
C link line (see the README, "In a simulator"). The interface is the
C Abaqus User Subroutines Reference's (FRIC_COEF): fCoef(nBlock,2),
C fCoefDeriv(nBlock,20,2), the derivative with respect to the contact
C pressure at index i_fDer_Pressure = 2, isotropic friction (the first
C direction only). Every entry of fCoefDeriv is written (dmu/dp at
C (k,2,1), zeros elsewhere: nothing says Abaqus clears it before the
C call); fCoef(:,2), the second direction, is left as Abaqus passed it.
C
C Units: Abaqus passes the contact pressure in the model's own stress
C unit (MPa in an N-mm model), so H, p_min and p_max are given in that
C unit too: mu depends on p/H only, and dmu/dp comes out per that unit.
C
C props (*FRICTION, USER=COEFFICIENT, PROPERTIES=n):
C   psi, theta, H (the model's stress unit)    n = 3
C   ... , p_min, p_max (same unit; 0, 0: 1e-5*H to 0.1*H)   n = 5
C   ... , beta, nu, eps_star                   n = 8
C The law of a props list is built once (about 20 ms) by the library
C and shared by every later call with the same values, from any thread
C (kef_law_from_props: a thread-safe cache inside libkefriction; this
C routine keeps no state, so it is safe to call from several threads).
C Pressures outside [p_min, p_max] get mu at the nearest end and a zero
C derivative. A node at p <= 0 (first touch, opening) gets mu at p_min
C and a zero derivative: the stick limit mu*p is 0 there anyway.
C p = +inf gets mu at p_max (clamped); a NaN pressure gets mu = NaN.
C Props the library refuses stop the analysis (XIT) with its message.
C
C Fixed-form Fortran with the C interfaces written out, so that the file
C compiles alone with the compiler Abaqus uses.
      SUBROUTINE FRIC_COEF(fCoef, fCoefDeriv, nBlock, nProps, nTemp,
     *   nFields, iData, rData, surfInt, surfSec, surfMain, props,
     *   slipData, pressure, tempAvg, fieldAvg)
      INCLUDE 'ABA_PARAM.INC'
      DIMENSION fCoef(nBlock,2), fCoefDeriv(nBlock,20,2),
     *   props(nProps), slipData(nBlock,6), pressure(nBlock),
     *   tempAvg(nBlock), fieldAvg(nBlock,nFields)
      DIMENSION iData(*), rData(*)
      CHARACTER*80 surfInt, surfSec, surfMain
C     The include must come first, so the C calls (which need USE
C     statements, and those must precede the include's IMPLICIT) live in
C     KEF_FRIC_COEF, with every argument's type explicit.
      CALL KEF_FRIC_COEF(fCoef, fCoefDeriv, nBlock, nProps, props,
     *   pressure)
      RETURN
      END
C
C The work of FRIC_COEF: mu into fCoef(:,1), dmu/dp into
C fCoefDeriv(:,2,1), every other entry of fCoefDeriv 0.
      SUBROUTINE KEF_FRIC_COEF(fCoef, fCoefDeriv, nBlock, nProps, props,
     *   pressure)
      USE, INTRINSIC :: ISO_C_BINDING
      IMPLICIT NONE
      INTEGER nBlock, nProps
      REAL(C_DOUBLE) fCoef(nBlock,2), fCoefDeriv(nBlock,20,2),
     *   props(nProps), pressure(nBlock)
      INTEGER i_fDer_SlipRateMag, i_fDer_Pressure, i_fDer_Temperature
      PARAMETER (i_fDer_SlipRateMag = 1, i_fDer_Pressure = 2,
     *   i_fDer_Temperature = 3)
      INTERFACE
        FUNCTION kef_law_from_props(n, props)
     *     BIND(C, NAME='kef_law_from_props')
          IMPORT :: C_PTR, C_DOUBLE, C_SIZE_T
          INTEGER(C_SIZE_T), VALUE :: n
          REAL(C_DOUBLE), DIMENSION(*), INTENT(IN) :: props
          TYPE(C_PTR) :: kef_law_from_props
        END FUNCTION
        FUNCTION kef_law_mu_and_derivative_batch_nan(law, n, p, mu,
     *     dmu_dp, n_nan)
     *     BIND(C, NAME='kef_law_mu_and_derivative_batch_nan')
          IMPORT :: C_PTR, C_DOUBLE, C_SIZE_T, C_INT
          TYPE(C_PTR), VALUE :: law
          INTEGER(C_SIZE_T), VALUE :: n
          REAL(C_DOUBLE), DIMENSION(*), INTENT(IN) :: p
          REAL(C_DOUBLE), DIMENSION(*), INTENT(INOUT) :: mu, dmu_dp
          INTEGER(C_SIZE_T), INTENT(OUT) :: n_nan
          INTEGER(C_INT) :: kef_law_mu_and_derivative_batch_nan
        END FUNCTION
        FUNCTION kef_law_range(law, p_min, p_max, hardness)
     *     BIND(C, NAME='kef_law_range')
          IMPORT :: C_PTR, C_DOUBLE, C_INT
          TYPE(C_PTR), VALUE :: law
          REAL(C_DOUBLE), INTENT(OUT) :: p_min, p_max, hardness
          INTEGER(C_INT) :: kef_law_range
        END FUNCTION
        FUNCTION kef_law_mu(law, p, mu) BIND(C, NAME='kef_law_mu')
          IMPORT :: C_PTR, C_DOUBLE, C_INT
          TYPE(C_PTR), VALUE :: law
          REAL(C_DOUBLE), VALUE :: p
          REAL(C_DOUBLE), INTENT(OUT) :: mu
          INTEGER(C_INT) :: kef_law_mu
        END FUNCTION
      END INTERFACE
      TYPE(C_PTR) law
      INTEGER(C_INT) code
      INTEGER(C_SIZE_T) nNan
      INTEGER k, j
      REAL(C_DOUBLE) pMin, pMax, hard, muMin
C
      law = kef_law_from_props(INT(nProps, C_SIZE_T), props)
      IF (.NOT. C_ASSOCIATED(law)) THEN
        CALL KEF_ABAQUS_STOP('kef_law_from_props')
      END IF
C     mu into fCoef(:,1), dmu/dp into fCoefDeriv(:,2,1): contiguous.
      code = kef_law_mu_and_derivative_batch_nan(law,
     *   INT(nBlock, C_SIZE_T), pressure, fCoef(1,1),
     *   fCoefDeriv(1,i_fDer_Pressure,1), nNan)
      IF (code .NE. 0) CALL KEF_ABAQUS_STOP('kef_law batch')
C     Every other derivative (slip rate, temperature, 4-20: the slip
C     rate's components and the slips; and the second direction's) is 0.
      DO j = 1, 20
        IF (j .NE. i_fDer_Pressure) THEN
          DO k = 1, nBlock
            fCoefDeriv(k,j,1) = 0.d0
          END DO
        END IF
        DO k = 1, nBlock
          fCoefDeriv(k,j,2) = 0.d0
        END DO
      END DO
      IF (nNan .GT. 0) THEN
C       Open nodes (p <= 0): mu at p_min, no slope.
        code = kef_law_range(law, pMin, pMax, hard)
        IF (code .EQ. 0) code = kef_law_mu(law, pMin, muMin)
        IF (code .NE. 0) CALL KEF_ABAQUS_STOP('kef_law_mu')
        DO k = 1, nBlock
          IF (pressure(k) .LE. 0.d0) THEN
            fCoef(k,1) = muMin
            fCoefDeriv(k,i_fDer_Pressure,1) = 0.d0
          END IF
        END DO
      END IF
      RETURN
      END
C
C Writes the library's message for the failed call WHAT and stops the
C analysis with Abaqus' XIT.
      SUBROUTINE KEF_ABAQUS_STOP(what)
      USE, INTRINSIC :: ISO_C_BINDING
      IMPLICIT NONE
      CHARACTER*(*) what
      INTERFACE
        FUNCTION kef_last_error() BIND(C, NAME='kef_last_error')
          IMPORT :: C_PTR
          TYPE(C_PTR) :: kef_last_error
        END FUNCTION
      END INTERFACE
      CHARACTER(KIND=C_CHAR), DIMENSION(:), POINTER :: chars
      CHARACTER*1024 message
      INTEGER n
      CALL C_F_POINTER(kef_last_error(), chars, [1024])
      message = ' '
      n = 0
      DO WHILE (n .LT. 1023)
        IF (chars(n + 1) .EQ. C_NULL_CHAR) EXIT
        n = n + 1
        message(n:n) = chars(n)
      END DO
      WRITE (6, '(4A)') 'ke-friction FRIC_COEF: ', what, ': ',
     *   message(1:MAX(n, 1))
      CALL XIT
      END
