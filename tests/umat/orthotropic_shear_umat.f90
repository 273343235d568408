! A small Abaqus-style UMAT written for pilempm's tests: isotropic normal response (E, nu)
! with three different shear moduli G12, G13, G23, so that a mix-up of the shear order
! (Abaqus: 11 22 33 12 13 23) shows. STATEV(1) accumulates |DSTRAN|, STATEV(2) counts the
! calls. An increment with a strain component above PROPS(6) is refused with PNEWDT = 0.5,
! as a UMAT asks its host for a smaller step.
      subroutine umat(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, drpldt, &
                      stran, dstran, time, dtime, temp, dtemp, predef, dpred, cmname, ndi, &
                      nshr, ntens, nstatv, props, nprops, coords, drot, pnewdt, celent, &
                      dfgrd0, dfgrd1, noel, npt, layer, kspt, kstep, kinc)
      implicit none
      character(len=80) :: cmname
      integer :: ndi, nshr, ntens, nstatv, nprops, noel, npt, layer, kspt, kstep, kinc
      double precision :: stress(ntens), statev(nstatv), ddsdde(ntens, ntens), sse, spd, scd, &
                          rpl, ddsddt(ntens), drplde(ntens), drpldt, stran(ntens), &
                          dstran(ntens), time(2), dtime, temp, dtemp, predef(1), dpred(1), &
                          props(nprops), coords(3), drot(3, 3), pnewdt, celent, &
                          dfgrd0(3, 3), dfgrd1(3, 3)
      double precision :: e, nu, lam, mu, limit
      integer :: i, j

      e = props(1)
      nu = props(2)
      limit = props(6)
      if (maxval(abs(dstran)) > limit) then
         pnewdt = 0.5d0
         return
      end if
      lam = e * nu / ((1.0d0 + nu) * (1.0d0 - 2.0d0 * nu))
      mu = e / (2.0d0 * (1.0d0 + nu))
      ddsdde = 0.0d0
      do i = 1, ndi
         do j = 1, ndi
            ddsdde(i, j) = lam
         end do
         ddsdde(i, i) = lam + 2.0d0 * mu
      end do
      ddsdde(4, 4) = props(3)
      ddsdde(5, 5) = props(4)
      ddsdde(6, 6) = props(5)
      stress = stress + matmul(ddsdde, dstran)
      statev(1) = statev(1) + sqrt(sum(dstran**2))
      statev(2) = statev(2) + 1.0d0
      end subroutine umat
