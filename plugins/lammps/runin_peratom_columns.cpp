#include "runin_peratom_columns.h"

using namespace LAMMPS_NS;

int RuninPeratomColumns::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  int m = 0;
  for (int k = 0; k < n; k++)
    for (const int c : forwarded) buf[m++] = columns[list[k]][c];
  return m;
}

void RuninPeratomColumns::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  for (int i = first; i < first + n; i++)
    for (const int c : forwarded) columns[i][c] = buf[m++];
}
